#pragma once
// The Bsdf at a hit, built as an integrator builds it, for the BSDF and microfacet tests.

#include "glint/materials/bsdf.h"
#include "glint/math/constants.h"

#include <cmath>

namespace glint_test {

inline const glint::Vec3 kUp(0.0f, 0.0f, 1.0f);

/// The unit direction at polar angle θ from +z and azimuth φ from +x, both in degrees.
inline glint::Vec3 from_polar(float theta_degrees, float phi_degrees = 0.0f) {
    const float t = glint::radians(theta_degrees), p = glint::radians(phi_degrees);
    return glint::Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

/// The Bsdf of `m`, which has no textures: its values are its own at every hit.
inline glint::Bsdf bsdf_of(const glint::Material& m, const glint::Vec3& n, const glint::Vec3& ng, const glint::Vec3& wo,
                           glint::Interface media) {
    return glint::Bsdf(m, glint::material_at_hit(m, glint::Vec2(), glint::Vec3()), n, ng, wo, media);
}

}  // namespace glint_test
