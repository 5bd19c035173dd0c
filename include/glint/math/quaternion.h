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

/// The shorter arc from `a` to `b`, set up once for many points on it (a moving object's
/// rotation at every ray's time): each point costs one sincos, where slerp() takes an acos,
/// three sines and a normalisation. at(s) is slerp(a, b, s) to rounding.
class SlerpArc {
public:
    SlerpArc(const Quaternion& a, const Quaternion& b);
    [[nodiscard]] Quaternion at(double s) const;

private:
    Quaternion a_, b_;    // b_ on a_'s side of the sphere: q and −q are the same rotation
    double theta_ = 0.0;  // the arc's angle on the unit sphere; 0 where the blend is linear
    double cot_theta_ = 0.0, inv_sin_theta_ = 0.0;
};

}  // namespace glint
