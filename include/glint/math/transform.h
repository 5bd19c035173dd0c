#pragma once
/// \file Affine 4x4 transforms that carry their inverse.
///
/// Names follow pbrt's `BFromA` habit in the code that uses them: a `Transform`
/// stored as `world_from_object` maps object-space points to world space.

#include "glint/math/bounds3.h"
#include "glint/math/ray.h"
#include "glint/math/vec3.h"

#include <array>

namespace glint {

/// Row-major 4x4 matrix; m[row][col], column vectors (p' = M·p).
struct Matrix4 {
    std::array<std::array<float, 4>, 4> m{};

    [[nodiscard]] static Matrix4 identity();
    [[nodiscard]] Matrix4 operator*(const Matrix4& o) const;
    [[nodiscard]] Matrix4 transposed() const;
    /// Whether the last row is exactly 0, 0, 0, 1.
    [[nodiscard]] bool is_affine() const { return m[3] == std::array<float, 4>{0.0f, 0.0f, 0.0f, 1.0f}; }
    /// General inverse by cofactors in double precision; returns false if singular.
    [[nodiscard]] bool inverse(Matrix4& out) const;
    bool operator==(const Matrix4&) const = default;
};

class Transform {
public:
    /// The identity.
    Transform();
    /// From a matrix; throws std::invalid_argument if it is singular.
    explicit Transform(const Matrix4& m);
    Transform(const Matrix4& m, const Matrix4& inverse) : m_(m), inv_(inverse) {}

    [[nodiscard]] static Transform translate(const Vec3& t);
    [[nodiscard]] static Transform scale(const Vec3& s);
    /// Rotation by `degrees` about `axis` (right-handed, counter-clockwise looking down the axis).
    [[nodiscard]] static Transform rotate(float degrees, const Vec3& axis);

    /// this ∘ other: apply `other` first, then this.
    [[nodiscard]] Transform operator*(const Transform& other) const;
    [[nodiscard]] Transform inverse() const { return Transform(inv_, m_); }
    [[nodiscard]] bool is_identity() const;
    [[nodiscard]] const Matrix4& matrix() const { return m_; }
    [[nodiscard]] const Matrix4& inverse_matrix() const { return inv_; }

    /// Points get the translation.
    [[nodiscard]] Vec3 point(const Vec3& p) const;
    /// Directions do not.
    [[nodiscard]] Vec3 vector(const Vec3& v) const;
    /// Normals transform by the inverse transpose so they stay perpendicular to surfaces;
    /// the result is not normalised.
    [[nodiscard]] Vec3 normal(const Vec3& n) const;
    /// Same t on both sides: the direction is transformed, not renormalised.
    [[nodiscard]] Ray ray(const Ray& r) const;
    /// Box around the eight transformed corners.
    [[nodiscard]] Bounds3 bounds(const Bounds3& b) const;
    /// True if the transform flips orientation (negative determinant of the linear part).
    [[nodiscard]] bool swaps_handedness() const;

    bool operator==(const Transform&) const = default;

private:
    Matrix4 m_;
    Matrix4 inv_;
};

}  // namespace glint
