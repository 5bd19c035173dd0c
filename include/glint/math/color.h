#pragma once
/// \file Linear RGB colour (radiance, reflectance, light intensity).
///
/// Every colour inside Glint is linear Rec.709/sRGB-primaries RGB. sRGB encoding only
/// happens when reading 8-bit colour textures (decoded) and writing PNG/JPEG (encoded).

#include <algorithm>
#include <cmath>
#include <ostream>

namespace glint {

struct Color {
    float r = 0.0f, g = 0.0f, b = 0.0f;

    constexpr Color() = default;
    constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Color(float s) : r(s), g(s), b(s) {}

    constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }

    constexpr Color operator+(const Color& o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Color operator-(const Color& o) const { return {r - o.r, g - o.g, b - o.b}; }
    /// Component-wise product: filtering light by a reflectance.
    constexpr Color operator*(const Color& o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Color operator*(float s) const { return {r * s, g * s, b * s}; }
    constexpr Color operator/(float s) const { return {r / s, g / s, b / s}; }
    constexpr Color& operator+=(const Color& o) { r += o.r; g += o.g; b += o.b; return *this; }
    constexpr Color& operator*=(const Color& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    constexpr Color& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Color&) const = default;

    [[nodiscard]] constexpr bool is_black() const { return r == 0.0f && g == 0.0f && b == 0.0f; }
    [[nodiscard]] constexpr float max_component() const { return std::max({r, g, b}); }
    /// Rec.709 relative luminance.
    [[nodiscard]] constexpr float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
    [[nodiscard]] bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

constexpr Color operator*(float s, const Color& c) { return c * s; }

/// Linear interpolation (1-t)·a + t·b.
[[nodiscard]] constexpr Color lerp(float t, const Color& a, const Color& b) { return a * (1.0f - t) + b * t; }

/// sRGB electro-optical transfer function (IEC 61966-2-1): encoded value in [0,1] → linear.
[[nodiscard]] inline float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}
/// Inverse of srgb_to_linear: linear → sRGB-encoded value (input clamped to [0,1]).
[[nodiscard]] inline float linear_to_srgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

inline std::ostream& operator<<(std::ostream& os, const Color& c) {
    return os << '[' << c.r << ", " << c.g << ", " << c.b << ']';
}

}  // namespace glint
