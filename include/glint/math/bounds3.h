#pragma once
/// \file Axis-aligned bounding box.

#include "glint/math/ray.h"
#include "glint/math/vec3.h"

#include <algorithm>

namespace glint {

struct Bounds3 {
    /// An empty box (lo > hi) so that extending it by anything gives that thing.
    Vec3 lo{kInfinity};
    Vec3 hi{-kInfinity};

    constexpr Bounds3() = default;
    constexpr Bounds3(const Vec3& lo_, const Vec3& hi_) : lo(lo_), hi(hi_) {}

    [[nodiscard]] bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const Vec3& p) { lo = min(lo, p); hi = max(hi, p); }
    void extend(const Bounds3& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
    [[nodiscard]] Vec3 center() const { return (lo + hi) * 0.5f; }
    [[nodiscard]] Vec3 diagonal() const { return hi - lo; }
    [[nodiscard]] float half_area() const {
        const Vec3 d = diagonal();
        return empty() ? 0.0f : d.x * d.y + d.y * d.z + d.z * d.x;
    }
    [[nodiscard]] bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
    }

    /// Slab test (Kay & Kajiya 1986) with a precomputed reciprocal direction; returns the
    /// entry/exit interval clipped to [tmin, tmax] or false when it is empty.
    [[nodiscard]] bool intersect(const Vec3& origin, const Vec3& inv_dir, float tmin, float tmax, float& t_enter,
                                 float& t_exit) const {
        for (int a = 0; a < 3; ++a) {
            float t0 = (lo[a] - origin[a]) * inv_dir[a];
            float t1 = (hi[a] - origin[a]) * inv_dir[a];
            if (t0 > t1) std::swap(t0, t1);
            // NaN from 0·inf (origin on a slab plane, direction parallel) keeps the old value.
            tmin = t0 > tmin ? t0 : tmin;
            tmax = t1 < tmax ? t1 : tmax;
        }
        t_enter = tmin;
        t_exit = tmax;
        return tmin <= tmax;
    }
};

[[nodiscard]] inline Bounds3 merge(const Bounds3& a, const Bounds3& b) { return {min(a.lo, b.lo), max(a.hi, b.hi)}; }

}  // namespace glint
