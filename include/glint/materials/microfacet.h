#pragma once
/// \file The Trowbridge-Reitz (GGX) microfacet distribution, in the local shading frame
/// (z = the normal): its normal density D, Smith's masking, and the sampling of visible normals.
///
/// Trowbridge & Reitz 1975; Walter, Marschner, Li & Torrance, "Microfacet Models for
/// Refraction through Rough Surfaces", EGSR 2007 (eqs. 33-34, where it is called GGX);
/// Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2),
/// 2014 (Λ and the height-correlated G); Heitz, "Sampling the GGX Distribution of Visible
/// Normals", JCGT 7(4), 2018. The formulas follow pbrt-v4 (section 9.6).

#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <algorithm>

namespace glint {

/// The smallest alpha a glossy lobe gets. Roughness just above 0 would give alpha² far
/// below float's reach in D's 1/α² (and D's peak 1/(πα²) is ~3·10⁷ here already), so alpha
/// stops at 1e-4, pbrt-v4's floor; roughness 0 itself is the delta mirror, not this.
inline constexpr float kMinMicrofacetAlpha = 1e-4f;

/// alpha = roughness², the perceptual mapping of Burley 2012 (Disney) that glTF 2.0 uses:
/// equal steps of roughness look like equal steps of blur. Floored at kMinMicrofacetAlpha.
[[nodiscard]] inline float roughness_to_alpha(float roughness) {
    return std::max(roughness * roughness, kMinMicrofacetAlpha);
}

/// GGX with widths alpha_x and alpha_y along the frame's x and y (isotropic when equal).
/// Directions are unit vectors in the shading frame; microfacet normals wm have wm.z > 0.
class TrowbridgeReitz {
public:
    TrowbridgeReitz() = default;
    TrowbridgeReitz(float alpha_x, float alpha_y) : alpha_x_(alpha_x), alpha_y_(alpha_y) {}

    /// Density of microfacet normals per unit solid angle, normalised so that
    /// ∫ D(wm) cos θm dωm = 1: D = 1 / (π αx αy (x²/αx² + y²/αy² + z²)²) (Walter eq. 33 with
    /// cos⁴θ (1 + tan²θ (cos²φ/αx² + sin²φ/αy²))² written in Cartesian form, which needs no
    /// tan θ and cannot overflow at grazing normals).
    [[nodiscard]] float D(const Vec3& wm) const;
    /// Smith's Λ(w) = (√(1 + α(φ)² tan²θ) − 1)/2 with α(φ)² = αx² cos²φ + αy² sin²φ (Heitz
    /// 2014, eq. 86); infinite on the horizon.
    [[nodiscard]] float lambda(const Vec3& w) const;
    /// Masking of one direction: G1 = 1/(1 + Λ(w)).
    [[nodiscard]] float G1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
    /// Height-correlated masking-shadowing: G = 1/(1 + Λ(wo) + Λ(wi)) (Heitz 2014, eq. 99).
    [[nodiscard]] float G(const Vec3& wo, const Vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }
    /// Density of the normals visible from w: G1(w)/|cos θw| · D(wm) · (w·wm) (Heitz 2014,
    /// eq. 2), 0 for normals facing away from w. For w under the surface, the normals visible
    /// from −w's mirror image above it (as sample_wm sees w). Integrates to 1 over wm.
    [[nodiscard]] float D(const Vec3& w, const Vec3& wm) const;
    /// A visible normal for w, distributed as D(w, wm): Heitz 2018's method (stretch w into
    /// the configuration of α = 1, sample the projected hemisphere there, unstretch), with
    /// the concentric disk map (as pbrt-v4) so that stratified u stay stratified.
    [[nodiscard]] Vec3 sample_wm(const Vec3& w, Vec2 u) const;
    /// Density of sample_wm per unit solid angle of wm: D(w, wm).
    [[nodiscard]] float pdf(const Vec3& w, const Vec3& wm) const { return D(w, wm); }

    [[nodiscard]] float alpha_x() const { return alpha_x_; }
    [[nodiscard]] float alpha_y() const { return alpha_y_; }

private:
    float alpha_x_ = 1.0f, alpha_y_ = 1.0f;
};

}  // namespace glint
