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
        // Clamped so that a broken normal (NaN or infinite, from degenerate input geometry)
        // cannot make the float-to-int conversion undefined: max(-k, NaN) is -k. Branch-free,
        // and the integer step is unsigned, as this runs for every secondary ray.
        const float scaled = std::min(kIntScale, std::max(-kIntScale, kIntScale * n[a]));
        const auto offset = static_cast<int32_t>(scaled);
        const auto bits = std::bit_cast<uint32_t>(p[a]);
        const float p_int = std::bit_cast<float>(bits + static_cast<uint32_t>(p[a] < 0.0f ? -offset : offset));
        result[a] = std::abs(p[a]) < kOrigin ? p[a] + kFloatScale * n[a] : p_int;
    }
    return result;
}

}  // namespace glint
