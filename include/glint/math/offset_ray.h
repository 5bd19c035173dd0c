#pragma once
/// \file Spawning secondary rays without self-intersection, at any scene scale.

#include "glint/math/vec3.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace glint {

/// Move a hit point off its surface along the geometric normal `n` (pointing to the side
/// the new ray leaves into). The offset grows with the magnitude of p, in units of the
/// float spacing there, so it works for scenes at millimetre and kilometre scale alike.
/// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
/// Ray Tracing Gems (2019), chapter 6.
[[nodiscard]] inline Vec3 offset_ray_origin(const Vec3& p, const Vec3& n) {
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    Vec3 result;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(p[a]) < kOrigin) {
            result[a] = p[a] + kFloatScale * n[a];
            continue;
        }
        // A broken normal (NaN or infinite, from degenerate input geometry) must not make
        // the float-to-int conversion undefined: no offset for NaN, a unit normal's at most.
        const float scaled = kIntScale * n[a];
        const auto offset = scaled == scaled ? static_cast<int32_t>(std::clamp(scaled, -kIntScale, kIntScale)) : 0;
        const int32_t bits = std::bit_cast<int32_t>(p[a]);
        result[a] = std::bit_cast<float>(bits + (p[a] < 0.0f ? -offset : offset));
    }
    return result;
}

}  // namespace glint
