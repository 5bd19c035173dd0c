#pragma once
/// \file The scattering function of a material at one hit (the seam every integrator uses).
///
/// A `Bsdf` is built from a `Material` and its values where a ray hit it (MaterialAtHit: kd,
/// kr and the roughness after textures), with the shading normal turned towards the viewer
/// (surfaces are two-sided). It holds the material's lobes, each with the weight the Whitted
/// material equation gives it (docs/shading.md):
///
///   smooth lobes   Lambert            f = (1−t)·kd·tex / π
///                  Blinn-Phong        f = (1−t)·ks·(N·H)^s / π   (the seminar's highlight)
///   delta lobes    mirror             (1−t)·kr, or Schlick with F0 = kr for metals
///   (roughness 0)  dielectric         t·F reflected, t·(1−F) transmitted (Schlick's F)
///   glossy lobes   GGX conductor      (1−t)·D·G·F/(4 cosθo cosθi), F = kr or Schlick(F0 = kr)
///   (roughness>0)  rough dielectric   t·(Walter et al. 2007's f_r + f_t)  (materials/microfacet_lobes.h)
///
/// Roughness > 0 turns the mirror and the glass into the glossy lobes (alpha = roughness²,
/// materials/microfacet.h); roughness 0 keeps the deltas, bit for bit. A dielectric whose two
/// indices are equal stays a delta at any roughness: its refraction does not bend rays.
///
/// BRDFs are physical (the Lambert lobe of albedo kd is kd/π); lights return physical
/// radiance or irradiance (lights/light.h), so f·L·cosθ/pdf is the same estimate in both
/// integrators. `eval` and `pdf` see the smooth and glossy lobes (the glossy ones are smooth
/// too: they have densities); `sample` picks any lobe with a probability proportional to its
/// weight (Veach 1997, §9.2: one-sample mixture sampling). Only a rough dielectric scatters
/// to under the surface; every other lobe is zero there.

#include "glint/materials/material.h"
#include "glint/materials/material_at_hit.h"
#include "glint/materials/microfacet_lobes.h"
#include "glint/materials/optics.h"
#include "glint/math/color.h"
#include "glint/math/constants.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace glint {

/// What kind of scattering a sampled direction came from (bit flags).
enum BsdfFlags : uint8_t {
    kBsdfReflection = 1,
    kBsdfTransmission = 2,
    /// A Dirac delta lobe (mirror, smooth glass): its pdf is not a density, and light
    /// sampling cannot reach it.
    kBsdfDelta = 4,
};

struct BsdfSample {
    /// Unit direction the light arrives from (world space).
    Vec3 wi;
    /// f·|cos θi| / pdf: the factor the path throughput is multiplied by.
    Color weight;
    /// Solid-angle density of wi over all smooth lobes (for MIS); for a delta lobe, the
    /// probability with which that lobe was chosen.
    float pdf = 0.0f;
    uint8_t flags = 0;
};

/// The two indices of refraction at a dielectric hit, from the integrator's media stack.
struct Interface {
    /// Index of the medium the viewer (wo) is in.
    float eta_from = 1.0f;
    /// Index of the medium beyond the surface.
    float eta_to = 1.5f;
};

/// The perfectly specular part, for integrators that trace it deterministically (Whitted).
struct SpecularLobes {
    /// Weight of the mirror direction: the mirror lobe plus the dielectric's Fresnel reflection.
    Color reflection;
    /// Weight of the refracted direction (0 under total internal reflection).
    float transmission = 0.0f;
    Vec3 reflected;
    /// The refracted direction, if any.
    std::optional<Vec3> refracted;
};

/// The glossy lobes of a rough material, which work in the frame (b1, b2, n). At namespace
/// scope, not nested in Bsdf: clang decides std::optional<GlossyLobes> is not
/// default-constructible while Bsdf, holding one, is still being defined (member
/// initialisers are parsed only at its end), and then refuses emplace().
struct GlossyLobes {
    Vec3 b1, b2, wo_local;
    GlossyConductor conductor;
    float conductor_scale = 0.0f;  ///< 1 − t; 0 for no conductor
    RoughDielectric dielectric;
    float dielectric_scale = 0.0f;  ///< t; 0 for no rough dielectric
};

class Bsdf {
public:
    /// `at` holds kd, kr and the roughness at the hit (material_at_hit(m, ...)); the other
    /// parameters come from `m`. `n` is the unit shading normal and `ng` the unit geometric
    /// normal, both on the viewer's side; `wo` the unit direction to the viewer.
    /// Inline: built at every hit.
    Bsdf(const Material& m, const MaterialAtHit& at, const Vec3& n, const Vec3& ng, const Vec3& wo, Interface media)
        : n_(n), ng_(ng), wo_(wo) {
        const float t = std::clamp(m.transparency, 0.0f, 1.0f);
        diffuse_ = at.diffuse * (1.0f - t);
        // The highlight is the surface's, not the opaque layer's: glass shows it too, as in
        // the seminar and POV-Ray (its `phong` on a clear finish).
        highlight_ = m.specular;
        shininess_ = m.shininess;

        const bool rough = at.roughness > 0.0f;
        const Vec3 d = -wo;
        specular_.reflected = reflect(d, n);
        if (!rough) {
            Color mirror = at.reflectivity;
            if (m.fresnel_mirror) {
                // Schlick with a coloured F0 (metals): F = F0 + (1 − F0)(1 − cos θ)^5.
                const float c = 1.0f - std::clamp(dot(n, wo), 0.0f, 1.0f);
                const float c5 = c * c * c * c * c;
                mirror = at.reflectivity + (Color(1.0f) - at.reflectivity) * c5;
            }
            specular_.reflection = mirror * (1.0f - t);
        }
        if (t > 0.0f && !(rough && media.eta_from != media.eta_to)) {
            specular_.refracted = refract(d, n, media.eta_from, media.eta_to);
            eta_ = media.eta_to / media.eta_from;
            // Under total internal reflection all of the dielectric's weight is reflected.
            const float fresnel = specular_.refracted ? fresnel_schlick(d, n, media.eta_from, media.eta_to) : 1.0f;
            specular_.reflection += Color(t * fresnel);
            specular_.transmission = t * (1.0f - fresnel);
        }
        if (rough) add_glossy_lobes(at, m.fresnel_mirror, t, media);
    }

    /// False where eval(wi) is certainly zero: wi on neither side a lobe scatters to (above
    /// the shading and true surface for reflection, under both for a rough dielectric's
    /// transmission), or no lobe with a density at all. Cheaper than eval: a caller can skip
    /// a shadow ray on it and evaluate the lobes (a pow for the highlight) only for
    /// unoccluded light.
    [[nodiscard]] bool may_reflect(const Vec3& wi) const {
        const float cn = dot(n_, wi), cg = dot(ng_, wi);
        if (cn > 0.0f && cg > 0.0f) return !(diffuse_.is_black() && highlight_.is_black()) || glossy_;
        return transmits() && cn < 0.0f && cg < 0.0f;
    }

    /// Sum of the smooth and glossy lobes' f(wo, wi). Zero for wi under the shading or true
    /// surface but for a rough dielectric's transmission (under both). Inline: the Whitted
    /// integrator calls it for every light at every hit.
    [[nodiscard]] Color eval(const Vec3& wi) const { return eval_parts(wi).all; }
    /// eval(wi), and the glossy lobes' share of it (eval_glossy(wi)), evaluated once: the
    /// Whitted integrator weighs that share of a light sample against its glossy samples.
    struct EvalParts {
        Color all, glossy;
    };
    [[nodiscard]] EvalParts eval_parts(const Vec3& wi) const {
        // Reflection on the viewer's side of both the shading and the true surface.
        const float cn = dot(n_, wi), cg = dot(ng_, wi);
        if (cn <= 0.0f || cg <= 0.0f) {
            if (transmits() && cn < 0.0f && cg < 0.0f) {
                const Color glossy = eval_glossy(wi);
                return {glossy, glossy};
            }
            return {};
        }
        Color f = diffuse_ * kInvPi;
        const Vec3 half = wi + wo_;
        // wi = −wo has no half-vector (and lies under the surface for any wo above it).
        if (!highlight_.is_black() && dot(half, half) > 0.0f) {
            const Vec3 h = normalize(half);
            f += highlight_ * (std::pow(std::max(dot(n_, h), 0.0f), shininess_) * kInvPi);
        }
        Color glossy;
        if (glossy_) {
            glossy = eval_glossy(wi);
            f += glossy;
        }
        return {f, glossy};
    }
    /// Solid-angle density with which sample() returns wi through a smooth or glossy lobe.
    [[nodiscard]] float pdf(const Vec3& wi) const;
    /// Choose a lobe with `u_lobe`, then a direction with `u`. Empty if the BSDF is black or
    /// the direction falls on a side its lobe does not scatter to.
    [[nodiscard]] std::optional<BsdfSample> sample(float u_lobe, Vec2 u) const;

    /// The glossy lobes alone, for the Whitted integrator, which traces them with several
    /// samples and weighs direct light through them against those samples (MIS): their
    /// f(wo, wi), the density of sample_glossy, and a sample of them whose weight is
    /// f_glossy·|cos θi|/pdf_glossy.
    [[nodiscard]] Color eval_glossy(const Vec3& wi) const;
    [[nodiscard]] float glossy_pdf(const Vec3& wi) const;
    [[nodiscard]] std::optional<BsdfSample> sample_glossy(float u_lobe, Vec2 u) const;

    /// True if some smooth or glossy lobe has weight (light sampling can help).
    [[nodiscard]] bool has_smooth_lobes() const { return !diffuse_.is_black() || !highlight_.is_black() || glossy_; }
    /// True for a rough material with a mirror or a dielectric part.
    [[nodiscard]] bool has_glossy_lobes() const { return glossy_.has_value(); }
    /// The delta lobes; none (black, 0) for a rough material's mirror and glass.
    [[nodiscard]] const SpecularLobes& specular() const { return specular_; }
    [[nodiscard]] const Vec3& normal() const { return n_; }

private:
    /// Lobe selection probabilities, summing to 1 (or all 0 for a black BSDF).
    struct LobeChoice {
        float diffuse = 0.0f, highlight = 0.0f, conductor = 0.0f, dielectric = 0.0f, reflect = 0.0f, transmit = 0.0f;
    };
    /// The glossy lobes of a rough material (out of line: only rough materials pay for them).
    void add_glossy_lobes(const MaterialAtHit& at, bool fresnel_mirror, float t, Interface media);
    [[nodiscard]] LobeChoice lobe_choice() const;
    /// The conductor and dielectric alone, in proportion to their weights.
    [[nodiscard]] LobeChoice glossy_choice() const;
    [[nodiscard]] float conductor_weight() const;
    [[nodiscard]] float pdf(const Vec3& wi, const LobeChoice& p) const;
    [[nodiscard]] float glossy_density(const Vec3& wi, const LobeChoice& p) const;
    [[nodiscard]] float highlight_pdf(const Vec3& wi) const;
    /// A smooth or glossy sample from the lobes of `p` (weight f·|cos|/pdf over them), or a
    /// delta lobe's.
    [[nodiscard]] std::optional<BsdfSample> sample(float u_lobe, Vec2 u, const LobeChoice& p, bool glossy_only) const;
    /// True for a rough dielectric, the one lobe under the surface.
    [[nodiscard]] bool transmits() const { return glossy_ && glossy_->dielectric_scale > 0.0f; }
    [[nodiscard]] Vec3 to_local(const Vec3& w) const { return {dot(w, glossy_->b1), dot(w, glossy_->b2), dot(w, n_)}; }
    [[nodiscard]] Vec3 to_world(const Vec3& l) const { return glossy_->b1 * l.x + glossy_->b2 * l.y + n_ * l.z; }

    Vec3 n_, ng_, wo_;
    Color diffuse_;    ///< (1−t)·kd·tex
    Color highlight_;  ///< (1−t)·ks
    float shininess_ = 0.0f;
    SpecularLobes specular_;
    /// Relative index across the surface for the transmitted direction (eta_to/eta_from).
    float eta_ = 1.0f;

    /// Empty for a smooth material, whose Bsdf (built at every hit) then initialises none of it.
    std::optional<GlossyLobes> glossy_;
};

}  // namespace glint
