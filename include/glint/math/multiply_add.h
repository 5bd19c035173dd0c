#pragma once
/// \file a·b + c rounded one way, whatever the optimiser does.

#include "glint/math/vec3.h"

#include <cmath>

namespace glint {

/// a·b + c in one rounding where the CPU has FMA, in two where it has not (and the compiler
/// then fuses nothing). Written out where one ray and eight must agree: left to itself, the
/// compiler fuses different products of a scalar expression than of its vectorised loop or
/// of the SIMD code that traces eight rays at once.
[[gnu::always_inline]] inline float multiply_add(float a, float b, float c) {
#if defined(__FMA__)
    return std::fma(a, b, c);
#else
    return a * b + c;
#endif
}

/// a·b with its sums fused in one fixed order (z last), as SIMD code across lanes computes it.
[[gnu::always_inline]] inline float dot_fused(const Vec3& a, const Vec3& b) {
    return multiply_add(a.z, b.z, multiply_add(a.y, b.y, a.x * b.x));
}

}  // namespace glint
