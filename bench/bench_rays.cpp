#include "bench_rays.h"

#include <cmath>
#include <numbers>

namespace glint::bench {

namespace {

struct D3 {
    double x, y, z;
};
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double norm(D3 a) { return std::sqrt(dot(a, a)); }
D3 normalized(D3 a) { return a * (1.0 / norm(a)); }
D3 widen(const Vec3& v) { return {v.x, v.y, v.z}; }
D3 widen(const float* v) { return {v[0], v[1], v[2]}; }

BenchRay make_ray(D3 org, D3 dir, float tfar) {
    return {{float(org.x), float(org.y), float(org.z)}, 0.0f, {float(dir.x), float(dir.y), float(dir.z)}, tfar};
}

struct Frame {
    D3 lo, hi, c;
    double diag;
};

Frame mesh_frame(const MeshData& mesh) {
    Bounds3 b;
    for (const Vec3& p : mesh.positions) b.extend(p);
    Frame f{widen(b.lo), widen(b.hi), {}, 0.0};
    f.c = (f.lo + f.hi) * 0.5;
    f.diag = norm(f.hi - f.lo);
    return f;
}

uint64_t splitmix64(uint64_t& state) {
    state += 0x9E3779B97F4A7C15ull;
    uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

}  // namespace

std::vector<BenchRay> primary_rays(const MeshData& mesh, int width, int height) {
    const Frame fr = mesh_frame(mesh);
    const D3 eye = fr.c + D3{0.0, 1.0, 1.0} * (1.2 * fr.diag / std::sqrt(2.0));
    const D3 f = normalized(fr.c - eye);
    const D3 r = normalized(cross(f, {0.0, 1.0, 0.0}));
    const D3 u = cross(r, f);
    const double tan_half = std::tan(20.0 * std::numbers::pi / 180.0);
    const double aspect = double(width) / double(height);
    std::vector<BenchRay> rays;
    rays.reserve(size_t(width) * height);
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) {
            const double sx = (2.0 * (px + 0.5) / width - 1.0) * tan_half * aspect;
            const double sy = (1.0 - 2.0 * (py + 0.5) / height) * tan_half;
            rays.push_back(make_ray(eye, normalized(f + r * sx + u * sy), INFINITY));
        }
    return rays;
}

SecondaryRays secondary_rays(const MeshData& mesh, const std::vector<BenchRay>& primary,
                             const std::vector<PrimaryHit>& hits) {
    const Frame fr = mesh_frame(mesh);
    const D3 light = fr.c + D3{1.0, 1.5, 0.5} * fr.diag;
    SecondaryRays out;
    for (size_t i = 0; i < primary.size(); ++i) {
        if (hits[i].prim == UINT32_MAX) continue;
        const BenchRay& ray = primary[i];
        const D3 dir = widen(ray.dir);
        const D3 p = widen(ray.org) + dir * double(hits[i].t);
        const uint32_t* idx = &mesh.indices[3 * size_t(hits[i].prim)];
        const D3 v0 = widen(mesh.positions[idx[0]]), v1 = widen(mesh.positions[idx[1]]),
                 v2 = widen(mesh.positions[idx[2]]);
        const D3 ng = cross(v1 - v0, v2 - v0);
        D3 n = dir * -1.0;
        if (norm(ng) > 0.0) {
            n = normalized(ng);
            if (dot(n, dir) > 0.0) n = n * -1.0;
        }
        const D3 o = p + n * (1e-4 * fr.diag);
        const D3 to_light = light - o;
        const double dist = norm(to_light);
        out.shadow.push_back(make_ray(o, to_light * (1.0 / dist), float(dist)));

        uint64_t state = i;
        const double u1 = double(splitmix64(state) >> 40) * 0x1p-24;
        const double u2 = double(splitmix64(state) >> 40) * 0x1p-24;
        const double rho = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
        const double lx = rho * std::cos(phi), ly = rho * std::sin(phi), lz = std::sqrt(1.0 - u1);
        // Orthonormal basis about n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
        const double s = std::copysign(1.0, n.z);
        const double a = -1.0 / (s + n.z);
        const double b = n.x * n.y * a;
        const D3 b1{1.0 + s * n.x * n.x * a, s * b, -s * n.x};
        const D3 b2{b, s + n.y * n.y * a, -n.y};
        out.incoherent.push_back(make_ray(o, normalized(b1 * lx + b2 * ly + n * lz), INFINITY));
    }
    return out;
}

}  // namespace glint::bench
