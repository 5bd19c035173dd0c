#pragma once
/// \file Numeric constants and angle conversions used across Glint.

#include <limits>
#include <numbers>

namespace glint {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

[[nodiscard]] constexpr float radians(float degrees) { return degrees * (kPi / 180.0f); }
[[nodiscard]] constexpr float degrees(float radians) { return radians * (180.0f / kPi); }

}  // namespace glint
