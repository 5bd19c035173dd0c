#pragma once
/// \file Unit quaternions for interpolating rotations (Shoemake, "Animating Rotation with
/// Quaternion Curves", SIGGRAPH 1985), in double precision: they are made once per motion
/// key and per ray time, never per triangle.

#include <array>

namespace glint {

struct Quaternion {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

    /// The rotation of a proper orthogonal 3×3 matrix r[row][col] (determinant +1).
    [[nodiscard]] static Quaternion from_rotation(const std::array<std::array<double, 3>, 3>& r);
    /// The 3×3 rotation matrix this unit quaternion stands for.
    [[nodiscard]] std::array<std::array<double, 3>, 3> to_rotation() const;
};

[[nodiscard]] double dot(const Quaternion& a, const Quaternion& b);
/// The angle, in radians, of the shortest rotation taking `a` to `b` (0 to π).
[[nodiscard]] double angle_between(const Quaternion& a, const Quaternion& b);
/// Spherical linear interpolation along the shorter arc: constant angular speed from `a`
/// (s = 0) to `b` (s = 1).
[[nodiscard]] Quaternion slerp(const Quaternion& a, const Quaternion& b, double s);

}  // namespace glint
