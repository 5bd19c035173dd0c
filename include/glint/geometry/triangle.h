#pragma once
/// \file Ray-triangle intersection.

#include "glint/math/ray.h"
#include "glint/math/vec3.h"

namespace glint {

/// Result of a ray-triangle test: t and the barycentric weights (v, w) of v1 and v2
/// (the weight of v0 is 1 - v - w).
struct TriangleHit {
    float t;
    float v;
    float w;
};

/// The seminar's formulation: solve origin + t·d = v0 + v·e1 + w·e2 by Cramer's rule,
/// with the determinants written as scalar triple products:
///   n = e1 × e2, q = -d × r (r = origin - v0), s = -d·n,
///   t = r·n / s, v = q·e2 / s, w = -e1·q / s.
/// Accepts t strictly inside (tmin, tmax). Returns false for a miss, a parallel ray or a
/// zero-area triangle.
[[nodiscard]] inline bool intersect_triangle(const Ray& ray, const Vec3& v0, const Vec3& v1, const Vec3& v2,
                                             TriangleHit& out) {
    const Vec3 e1 = v1 - v0;
    const Vec3 e2 = v2 - v0;
    const Vec3 n = cross(e1, e2);
    const float s = -dot(ray.direction, n);
    if (s == 0.0f) return false;
    const float inv_s = 1.0f / s;
    const Vec3 r = ray.origin - v0;
    const float t = dot(r, n) * inv_s;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const Vec3 q = cross(-ray.direction, r);
    const float v = dot(q, e2) * inv_s;
    if (v < 0.0f) return false;
    const float w = -dot(e1, q) * inv_s;
    if (w < 0.0f || v + w > 1.0f) return false;
    out = {t, v, w};
    return true;
}

}  // namespace glint
