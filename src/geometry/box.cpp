#include "glint/geometry/box.h"

#include "glint/scene_format/param_table.h"

#include <algorithm>
#include <stdexcept>

namespace glint {

Box::Box(const Vec3& lo, const Vec3& hi) : box_(lo, hi) {
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z) || !is_finite(lo) || !is_finite(hi))
        throw std::invalid_argument("box needs finite corners with min < max on every axis");
}

bool Box::entry_or_exit(const Ray& ray, float& t, int& face) const {
    // Slab test keeping track of which face bounds the interval.
    float t_enter = -kInfinity, t_exit = kInfinity;
    int face_enter = -1, face_exit = -1;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / ray.direction[a];
        float t0 = (box_.lo[a] - ray.origin[a]) * inv;
        float t1 = (box_.hi[a] - ray.origin[a]) * inv;
        int f0 = 2 * a, f1 = 2 * a + 1;
        if (t0 > t1) {
            std::swap(t0, t1);
            std::swap(f0, f1);
        }
        if (t0 > t_enter) { t_enter = t0; face_enter = f0; }
        if (t1 < t_exit) { t_exit = t1; face_exit = f1; }
    }
    if (t_enter > t_exit) return false;
    if (t_enter > ray.tmin && t_enter < ray.tmax && face_enter >= 0) {
        t = t_enter;
        face = face_enter;
        return true;
    }
    if (t_exit > ray.tmin && t_exit < ray.tmax && face_exit >= 0) {
        t = t_exit;
        face = face_exit;
        return true;
    }
    return false;
}

bool Box::intersect(Ray& ray, Hit& hit) const {
    float t;
    int face;
    if (!entry_or_exit(ray, t, face)) return false;
    ray.tmax = t;
    hit.t = t;
    hit.primitive = static_cast<uint32_t>(face);
    hit.u = hit.v = 0.0f;
    return true;
}

bool Box::occluded(const Ray& ray) const {
    float t;
    int face;
    return entry_or_exit(ray, t, face);
}

void Box::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si, InteractionDetail) const {
    // Texture coordinates cost a few operations here: set at every detail.
    const int axis = static_cast<int>(hit.primitive) / 2;
    const bool positive = hit.primitive % 2 == 1;
    Vec3 n(0.0f);
    n[axis] = positive ? 1.0f : -1.0f;
    Vec3 p = ray.at(hit.t);
    p[axis] = positive ? box_.hi[axis] : box_.lo[axis];
    si.p = p;
    si.geometric_normal = n;
    si.shading_normal = n;
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const Vec3 d = box_.diagonal();
    si.uv = Vec2((p[a1] - box_.lo[a1]) / d[a1], (p[a2] - box_.lo[a2]) / d[a2]);
    si.dpdu[a1] = d[a1];
    si.dpdv[a2] = d[a2];
    si.front_face = dot(ray.direction, n) < 0.0f;
}

float Box::area() const {
    const Vec3 e = box_.hi - box_.lo;
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

std::optional<ShapeSample> Box::sample_area(Vec2 u, InteractionDetail /*uv costs nothing here*/) const {
    // Pick an axis pair of faces by their area, then one of the two faces, then a point.
    const Vec3 e = box_.hi - box_.lo;
    const float face_area[3] = {e.y * e.z, e.z * e.x, e.x * e.y};
    const float total = face_area[0] + face_area[1] + face_area[2];
    float x = u.x * total;
    int axis = 0;
    while (axis < 2 && x >= face_area[axis]) x -= face_area[axis++];
    x = std::clamp(x / face_area[axis], 0.0f, 1.0f);
    const bool upper = x >= 0.5f;
    const float s = upper ? 2.0f * x - 1.0f : 2.0f * x;
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    Vec3 p, n(0.0f);
    p[axis] = upper ? box_.hi[axis] : box_.lo[axis];
    p[a1] = box_.lo[a1] + s * e[a1];
    p[a2] = box_.lo[a2] + u.y * e[a2];
    n[axis] = upper ? 1.0f : -1.0f;
    return ShapeSample{p, n, Vec2(s, u.y), 1.0f / area()};
}

std::shared_ptr<Shape> Box::from_params(const ParamTable& t, const BuildContext&) {
    const Vec3 lo = t.require_vec3("min"), hi = t.require_vec3("max");
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) t.fail("max", "a corner above min on every axis");
    return std::make_shared<Box>(lo, hi);
}

}  // namespace glint
