#pragma once
/// \file The top three rows of an affine 4×4 matrix.

#include "glint/math/ray.h"
#include "glint/math/transform.h"
#include "glint/math/vec3.h"

#include <array>

namespace glint {

/// An affine map as its top three rows (the fourth is 0, 0, 0, 1): what a ray needs to
/// change space, in 48 bytes where a Transform keeps 128 (matrix and inverse). The top-level
/// traversal keeps one per object; the arithmetic is Transform's, term for term, so a ray
/// comes out the same.
struct Matrix3x4 {
    std::array<std::array<float, 4>, 3> m{};

    /// The top rows of `affine`, whose last row is 0, 0, 0, 1 (every Transform Glint makes:
    /// its steps are affine, and matrices from scene files are checked to be).
    [[nodiscard]] static Matrix3x4 of(const Matrix4& affine) {
        Matrix3x4 r;
        for (int i = 0; i < 3; ++i) r.m[i] = affine.m[i];
        return r;
    }

    [[nodiscard]] Vec3 point(const Vec3& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    [[nodiscard]] Vec3 vector(const Vec3& v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    /// Same t on both sides: the direction is transformed, not renormalised.
    [[nodiscard]] Ray ray(const Ray& r) const { return {point(r.origin), vector(r.direction), r.tmin, r.tmax, r.time}; }
};

}  // namespace glint
