#pragma once
/// \file Reflection, refraction and Fresnel: the optics of the Whitted integrator.

#include "glint/math/vec3.h"

#include <cmath>
#include <optional>

namespace glint {

/// Mirror direction of `incident` (pointing at the surface) about unit normal `n`:
/// r = i - 2(n·i)n (handout §5.3; the seminar's r = 2(n·v)n - v with v = -i).
[[nodiscard]] inline Vec3 reflect(const Vec3& incident, const Vec3& n) { return incident - n * (2.0f * dot(n, incident)); }

/// Refracted direction by Snell's law for unit `incident` through unit normal `n` facing
/// against it (n·i < 0), from index eta_from into eta_to:
///   η = eta_from/eta_to, r = -i·n, c = 1 - η²(1 - r²), t = η·i + (η·r - √c)·n (seminar).
/// Empty when c < 0: total internal reflection.
[[nodiscard]] inline std::optional<Vec3> refract(const Vec3& incident, const Vec3& n, float eta_from, float eta_to) {
    const float eta = eta_from / eta_to;
    const float r = -dot(incident, n);
    const float c = 1.0f - eta * eta * (1.0f - r * r);
    if (c < 0.0f) return std::nullopt;
    return incident * eta + n * (eta * r - std::sqrt(c));
}

/// Schlick's approximation of Fresnel reflectance (Schlick 1994; Shirley §10.7):
/// R = R0 + (1 - R0)(1 - cos θ)^5, R0 = ((n1 - n2)/(n1 + n2))². `cos_theta` is the cosine
/// on the side of the lower index (the transmitted side when going into a denser medium),
/// so that the approximation is right on both sides of the interface.
[[nodiscard]] inline float schlick(float cos_theta, float n1, float n2) {
    const float r0 = (n1 - n2) / (n1 + n2);
    const float f0 = r0 * r0;
    const float m = 1.0f - std::clamp(cos_theta, 0.0f, 1.0f);
    return f0 + (1.0f - f0) * m * m * m * m * m;
}

/// Fresnel reflectance of a ray with unit direction `incident` hitting an interface with
/// unit normal `n` (n·i < 0) from eta_from into eta_to; 1 under total internal reflection.
[[nodiscard]] inline float fresnel_schlick(const Vec3& incident, const Vec3& n, float eta_from, float eta_to) {
    const float cos_i = -dot(incident, n);
    if (eta_from <= eta_to) return schlick(cos_i, eta_from, eta_to);
    const auto t = refract(incident, n, eta_from, eta_to);
    if (!t) return 1.0f;
    return schlick(-dot(*t, n), eta_from, eta_to);
}

/// Critical angle (radians) for total internal reflection from eta_from into eta_to < eta_from.
[[nodiscard]] inline float critical_angle(float eta_from, float eta_to) { return std::asin(eta_to / eta_from); }

}  // namespace glint
