#pragma once
/// \file Three-component float vector, used for points, directions and normals.
///
/// Glint keeps one type for the three and makes the difference explicit where it
/// matters: `Transform::point`, `Transform::vector` and `Transform::normal` apply a
/// transform the way each kind needs. The world is right-handed, +y up by convention.

#include <algorithm>
#include <cmath>
#include <ostream>

namespace glint {

struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;

    constexpr Vec3() = default;
    constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3(float s) : x(s), y(s), z(s) {}

    constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
    constexpr Vec3 operator/(const Vec3& o) const { return {x / o.x, y / o.y, z / o.z}; }
    constexpr Vec3 operator*(float s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(float s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(float s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator*(float s, const Vec3& v) { return v * s; }

[[nodiscard]] constexpr float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
[[nodiscard]] constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
[[nodiscard]] constexpr float length_squared(const Vec3& v) { return dot(v, v); }
[[nodiscard]] inline float length(const Vec3& v) { return std::sqrt(dot(v, v)); }
[[nodiscard]] inline Vec3 normalize(const Vec3& v) { return v / length(v); }
/// `v` made unit length; a zero (or non-finite) length gives the zero vector.
[[nodiscard]] inline Vec3 unit_or_zero(const Vec3& v) {
    const float l = length(v);
    return l > 0.0f && std::isfinite(l) ? v / l : Vec3();
}
[[nodiscard]] inline Vec3 min(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
[[nodiscard]] inline Vec3 max(const Vec3& a, const Vec3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
[[nodiscard]] constexpr Vec3 lerp(float t, const Vec3& a, const Vec3& b) { return a * (1.0f - t) + b * t; }
[[nodiscard]] inline Vec3 abs(const Vec3& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
[[nodiscard]] inline float max_component(const Vec3& v) { return std::max({v.x, v.y, v.z}); }
[[nodiscard]] inline int max_axis(const Vec3& v) { return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2); }
[[nodiscard]] inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
/// Flip `v` so that it lies in the hemisphere of `reference`.
[[nodiscard]] constexpr Vec3 face_forward(const Vec3& v, const Vec3& reference) {
    return dot(v, reference) < 0.0f ? -v : v;
}

inline std::ostream& operator<<(std::ostream& os, const Vec3& v) {
    return os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}

}  // namespace glint
