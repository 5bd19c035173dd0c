#pragma once
/// \file A ray p(t) = origin + t·direction, valid for t in [tmin, tmax], at one scene time.

#include "glint/math/constants.h"
#include "glint/math/vec3.h"

namespace glint {

struct Ray {
    Vec3 origin;
    /// Not necessarily unit length: a ray carried into an object's space keeps its t.
    Vec3 direction;
    /// At least 0: a ray starts at its origin (the BVH's box test relies on it).
    float tmin = 0.0f;
    /// Closest-hit queries shrink tmax as they find closer hits.
    float tmax = kInfinity;
    /// The scene time the ray travels at (motion blur): moving objects are where they are
    /// then. Every ray spawned from a hit keeps its parent's time.
    float time = 0.0f;

    constexpr Ray() = default;
    constexpr Ray(const Vec3& o, const Vec3& d, float t0 = 0.0f, float t1 = kInfinity, float at_time = 0.0f)
        : origin(o), direction(d), tmin(t0), tmax(t1), time(at_time) {}

    [[nodiscard]] constexpr Vec3 at(float t) const { return origin + direction * t; }
};

}  // namespace glint
