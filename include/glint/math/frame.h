#pragma once
/// \file Orthonormal frame around a unit vector.

#include "glint/math/vec3.h"

#include <cmath>

namespace glint {

/// Two unit tangents b1, b2 with (b1, b2, n) right-handed and orthonormal, without branches
/// on a threshold: Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
inline void orthonormal_basis(const Vec3& n, Vec3& b1, Vec3& b2) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    b1 = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    b2 = Vec3(b, sign + n.y * n.y * a, -n.y);
}

}  // namespace glint
