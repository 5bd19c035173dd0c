// The heightfield: the mesh's watertight triangle test on a 2D grid walk (issue 13), so that
// it hits exactly what the same surface as a triangle list hits and never lets a ray through
// a shared edge or vertex.
#include "glint/geometry/heightfield.h"
#include "glint/geometry/triangle_mesh.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace glint;

namespace {

/// The same surface as a heightfield, as an explicit list of triangles.
MeshData heightfield_as_mesh(uint32_t nx, uint32_t nz, const std::vector<float>& h, Vec2 lo, Vec2 hi) {
    MeshData d;
    const float dx = (hi.x - lo.x) / float(nx - 1), dz = (hi.y - lo.y) / float(nz - 1);
    for (uint32_t j = 0; j < nz; ++j)
        for (uint32_t i = 0; i < nx; ++i)
            d.positions.emplace_back(lo.x + float(i) * dx, h[j * nx + i], lo.y + float(j) * dz);
    for (uint32_t j = 0; j + 1 < nz; ++j)
        for (uint32_t i = 0; i + 1 < nx; ++i) {
            const uint32_t a = j * nx + i, b = a + 1, c = a + nx, e = c + 1;
            d.indices.insert(d.indices.end(), {a, c, e, a, e, b});
        }
    return d;
}

}  // namespace

TEST(Heightfield, AgreesWithTriangleListOnRandomRays) {
    const uint32_t nx = 23, nz = 17;
    std::vector<float> h(nx * nz);
    for (uint32_t j = 0; j < nz; ++j)
        for (uint32_t i = 0; i < nx; ++i) h[j * nx + i] = 0.3f * std::sin(0.7f * float(i)) * std::cos(0.5f * float(j));
    const Vec2 lo(-2, -1), hi(3, 2);
    const Heightfield field(nx, nz, h, lo, hi);
    TriangleMesh mesh(heightfield_as_mesh(nx, nz, h, lo, hi));
    mesh.prepare();
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-4.0f, 4.0f);
    int hits = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 origin(u(rng), 2.0f + std::abs(u(rng)), u(rng));
        const Vec3 target(u(rng) * 0.7f, u(rng) * 0.1f, u(rng) * 0.5f);
        Ray r1(origin, normalize(target - origin)), r2 = r1;
        Hit h1, h2;
        const bool a = field.intersect(r1, h1), b = mesh.intersect(r2, h2);
        ASSERT_EQ(a, b) << "ray " << i;
        if (a) {
            ++hits;
            // The same watertight arithmetic, scalar in the heightfield and on SIMD lanes in
            // the mesh, with products fused alike: the same triangle, t and barycentrics, to
            // the bit.
            EXPECT_EQ(h1.primitive, h2.primitive) << "ray " << i;
            EXPECT_EQ(std::bit_cast<uint32_t>(h1.t), std::bit_cast<uint32_t>(h2.t)) << "ray " << i;
            EXPECT_EQ(std::bit_cast<uint32_t>(h1.u), std::bit_cast<uint32_t>(h2.u)) << "ray " << i;
            EXPECT_EQ(std::bit_cast<uint32_t>(h1.v), std::bit_cast<uint32_t>(h2.v)) << "ray " << i;
            EXPECT_EQ(field.occluded(Ray(origin, r1.direction)), true);
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(Heightfield, RaysThroughSharedEdgesAndVerticesNeverSlipThrough) {
    // Seen along a direction every triangle faces, the surface covers its extent without
    // folds: every such ray aimed at a point strictly inside it must hit, also through the
    // edges and vertices two to six triangles share (meshes' watertight test, Woop et al.
    // 2013, guarantees it). (A ray that sees a triangle edge-on may rightly skim a ridge.)
    const uint32_t nx = 9, nz = 7;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> h(nx * nz);
    for (float& y : h) y = 0.25f * u(rng) - 0.1f;
    const Vec2 lo(-1.3f, 0.7f), hi(2.9f, 3.1f);
    const Heightfield field(nx, nz, h, lo, hi);
    const MeshData grid = heightfield_as_mesh(nx, nz, h, lo, hi);
    // The rim is no shared edge: targets stay strictly inside the outermost vertices.
    const Vec3 first = grid.positions.front(), last = grid.positions.back();
    std::vector<Vec3> targets;
    for (std::size_t t = 0; t < grid.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = grid.positions[grid.indices[t + k]];
            const Vec3& b = grid.positions[grid.indices[t + (k + 1) % 3]];
            for (const float s : {0.0f, 0.5f, 0.25f, 1.0f / 3.0f, 0.9f})
                if (const Vec3 p = a + (b - a) * s; p.x > first.x && p.x < last.x && p.z > first.z && p.z < last.z)
                    targets.push_back(p);
        }
    int escaped = 0, rays = 0;
    for (const Vec3 offset : {Vec3(0.0f, 4.0f, 0.0f), Vec3(0.37f, 3.1f, -0.21f), Vec3(-1.0f, 2.9f, 0.6f)}) {
        for (std::size_t t = 0; t < grid.indices.size(); t += 3) {
            const Vec3 &a = grid.positions[grid.indices[t]], &b = grid.positions[grid.indices[t + 1]],
                       &c = grid.positions[grid.indices[t + 2]];
            ASSERT_GT(dot(cross(b - a, c - a), offset), 0.0f) << "triangle " << t / 3 << " does not face the rays";
        }
        for (const Vec3& target : targets) {
            const Ray ray(target + offset, -offset);
            Ray r = ray;
            Hit hit;
            ++rays;
            if (!field.intersect(r, hit) || !field.occluded(ray)) ++escaped;
        }
    }
    EXPECT_EQ(escaped, 0) << "of " << rays << " rays";
}

TEST(Heightfield, VerticalRayAndOutsideExtent) {
    const Heightfield field(2, 2, {1, 1, 1, 1}, Vec2(0, 0), Vec2(1, 1));
    Ray down({0.5f, 5, 0.5f}, {0, -1, 0});
    Hit h;
    ASSERT_TRUE(field.intersect(down, h));
    EXPECT_FLOAT_EQ(h.t, 4.0f);
    SurfaceInteraction si;
    field.interaction(down, h, si);
    EXPECT_NEAR(si.shading_normal.y, 1.0f, 1e-6f);
    EXPECT_NEAR(si.uv.x, 0.5f, 1e-5f);
    Ray outside({1.5f, 5, 0.5f}, {0, -1, 0});
    EXPECT_FALSE(field.intersect(outside, h));
}

TEST(Heightfield, RejectsBadGrids) {
    EXPECT_THROW(Heightfield(1, 2, {0, 0}, Vec2(0, 0), Vec2(1, 1)), std::invalid_argument);
    EXPECT_THROW(Heightfield(2, 2, {0, 0, 0}, Vec2(0, 0), Vec2(1, 1)), std::invalid_argument);
    EXPECT_THROW(Heightfield(2, 2, {0, 0, 0, 0}, Vec2(0, 0), Vec2(0, 1)), std::invalid_argument);
}
