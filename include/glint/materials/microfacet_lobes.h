#pragma once
/// \file The glossy lobes a rough material has instead of its delta mirror and glass: a GGX
/// conductor and Walter et al.'s rough dielectric. Both work in the local shading frame
/// (z = the shading normal, turned towards the viewer, so wo.z > 0) and leave the lobe weights
/// (1 − t for the mirror, t for the dielectric) to the Bsdf that holds them.

#include "glint/materials/microfacet.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <optional>

namespace glint {

/// Glossy reflection off a rough metal: f = D(wm)·G(wo, wi)·F / (4 cos θo cos θi), wm the
/// half-vector (Cook & Torrance 1982; Walter et al. 2007, eq. 20). F is the constant kr, or
/// Schlick's F0 + (1 − F0)(1 − wo·wm)^5 on the microfacet normal with the coloured F0 = kr.
class GlossyConductor {
public:
    GlossyConductor() = default;
    GlossyConductor(TrowbridgeReitz distribution, const Color& kr, bool schlick)
        : distribution_(distribution), kr_(kr), schlick_(schlick) {}

    /// f(wo, wi); zero unless both directions are above the surface.
    [[nodiscard]] Color eval(const Vec3& wo, const Vec3& wi) const;
    /// Density of sample(): the visible normal's D(wo, wm) times the reflection Jacobian
    /// dωm/dωi = 1/(4 |wo·wm|) (Walter et al. 2007, eq. 14).
    [[nodiscard]] float pdf(const Vec3& wo, const Vec3& wi) const;
    /// wi mirrored about a visible microfacet normal; empty if it falls under the surface.
    [[nodiscard]] std::optional<Vec3> sample(const Vec3& wo, Vec2 u) const;
    /// F for cos θ = wo·wm; the Bsdf takes it at the shading normal to weigh this lobe
    /// against the others when it chooses one.
    [[nodiscard]] Color fresnel(float cos_theta) const;

private:
    TrowbridgeReitz distribution_;
    Color kr_;
    bool schlick_ = false;
};

/// Reflection and refraction through a rough interface from index eta_from (the viewer's
/// side) into eta_to (Walter et al. 2007): with the generalised half-vector
/// wm = ±normalize(wo + η wi), η = eta_to/eta_from for transmission and 1 for reflection (eq. 16),
///   reflection    f_r = F·D·G / (4 |cos θo| |cos θi|)                                   (eq. 20)
///   transmission  f_t = (1 − F)·D·G·|wi·wm| |wo·wm| / (|cos θo| |cos θi| (η wi·wm + wo·wm)²)
/// which is eq. 21 for radiance: its η_o² over the squared sum is pbrt-v4's BTDF divided by
/// η², the compression of radiance entering a denser medium (Veach 1997, §5.2), as the delta
/// glass applies it. F is Schlick's reflectance of the microfacet (materials/optics.h), 1
/// under total internal reflection.
class RoughDielectric {
public:
    RoughDielectric() = default;
    RoughDielectric(TrowbridgeReitz distribution, float eta_from, float eta_to)
        : distribution_(distribution), eta_from_(eta_from), eta_to_(eta_to) {}

    /// f_r for wi above the surface, f_t for wi under it.
    [[nodiscard]] float eval(const Vec3& wo, const Vec3& wi) const;
    /// Density of sample(): D(wo, wm) times F for reflection with the Jacobian 1/(4|wo·wm|),
    /// or times 1 − F for refraction with Walter's eq. 17, dωm/dωi = η²|wi·wm| / (η wi·wm + wo·wm)².
    [[nodiscard]] float pdf(const Vec3& wo, const Vec3& wi) const;
    /// A visible microfacet normal from u, then reflection with probability F (chosen by
    /// u_choice) or refraction; empty if the direction falls on the wrong side.
    [[nodiscard]] std::optional<Vec3> sample(const Vec3& wo, float u_choice, Vec2 u) const;

private:
    /// The microfacet normal that takes wo to wi (facing +z), or nothing for a degenerate
    /// pair or a back-facing microfacet (Walter et al. 2007, eq. 16 and the paragraph after).
    [[nodiscard]] std::optional<Vec3> half_vector(const Vec3& wo, const Vec3& wi) const;
    /// Schlick's reflectance of the microfacet with normal wm seen from wo.
    [[nodiscard]] float fresnel(const Vec3& wo, const Vec3& wm) const;

    TrowbridgeReitz distribution_;
    float eta_from_ = 1.0f, eta_to_ = 1.5f;
};

}  // namespace glint
