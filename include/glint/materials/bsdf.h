#pragma once
/// \file The scattering function of a material at one hit (the seam every integrator uses).
///
/// A `Bsdf` is built from a `Material` where a ray hit it, with the shading normal turned
/// towards the viewer (surfaces are two-sided). It holds the material's lobes, each with the
/// weight the Whitted material equation gives it (docs/shading.md):
///
///   smooth lobes   Lambert            f = (1−t)·kd·tex / π
///                  Blinn-Phong        f = (1−t)·ks·(N·H)^s / π   (the seminar's highlight)
///   delta lobes    mirror             (1−t)·kr, or Schlick with F0 = kr for metals
///                  dielectric         t·F reflected, t·(1−F) transmitted (Schlick's F)
///
/// BRDFs are physical (the Lambert lobe of albedo kd is kd/π); lights return physical
/// radiance or irradiance (lights/light.h), so f·L·cosθ/pdf is the same estimate in both
/// integrators. `eval` and `pdf` see only the smooth lobes; `sample` picks any lobe with a
/// probability proportional to its weight (Veach 1997, §9.2: one-sample mixture sampling).

#include "glint/materials/material.h"
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

class Bsdf {
public:
    /// `texture` multiplies kd (white for none). `n` is the unit shading normal and `ng` the
    /// unit geometric normal, both on the viewer's side; `wo` the unit direction to the viewer.
    /// Inline: built at every hit.
    Bsdf(const Material& m, const Color& texture, const Vec3& n, const Vec3& ng, const Vec3& wo, Interface media)
        : n_(n), ng_(ng), wo_(wo) {
        const float t = std::clamp(m.transparency, 0.0f, 1.0f);
        diffuse_ = m.diffuse * texture * (1.0f - t);
        highlight_ = m.specular * (1.0f - t);
        shininess_ = m.shininess;

        const Vec3 d = -wo;
        specular_.reflected = reflect(d, n);
        Color mirror = m.reflectivity;
        if (m.fresnel_mirror) {
            // Schlick with a coloured F0 (metals): F = F0 + (1 − F0)(1 − cos θ)^5.
            const float c = 1.0f - std::clamp(dot(n, wo), 0.0f, 1.0f);
            const float c5 = c * c * c * c * c;
            mirror = m.reflectivity + (Color(1.0f) - m.reflectivity) * c5;
        }
        specular_.reflection = mirror * (1.0f - t);
        if (t > 0.0f) {
            specular_.refracted = refract(d, n, media.eta_from, media.eta_to);
            eta_ = media.eta_to / media.eta_from;
            // Under total internal reflection all of the dielectric's weight is reflected.
            const float fresnel = specular_.refracted ? fresnel_schlick(d, n, media.eta_from, media.eta_to) : 1.0f;
            specular_.reflection += Color(t * fresnel);
            specular_.transmission = t * (1.0f - fresnel);
        }
    }

    /// False where eval(wi) is certainly zero: wi under the shading or true surface, or no
    /// smooth lobe at all. Cheaper than eval: a caller can skip a shadow ray on it and
    /// evaluate the lobes (a pow for the highlight) only for unoccluded light.
    [[nodiscard]] bool may_reflect(const Vec3& wi) const {
        return dot(n_, wi) > 0.0f && dot(ng_, wi) > 0.0f && !(diffuse_.is_black() && highlight_.is_black());
    }

    /// Sum of the smooth lobes' f(wo, wi); zero for wi under the shading or true surface.
    /// Inline: the Whitted integrator calls it for every light at every hit.
    [[nodiscard]] Color eval(const Vec3& wi) const {
        // Reflection only, on the viewer's side of both the shading and the true surface.
        if (dot(n_, wi) <= 0.0f || dot(ng_, wi) <= 0.0f) return Color();
        Color f = diffuse_ * kInvPi;
        const Vec3 half = wi + wo_;
        // wi = −wo has no half-vector (and lies under the surface for any wo above it).
        if (!highlight_.is_black() && dot(half, half) > 0.0f) {
            const Vec3 h = normalize(half);
            f += highlight_ * (std::pow(std::max(dot(n_, h), 0.0f), shininess_) * kInvPi);
        }
        return f;
    }
    /// Solid-angle density with which sample() returns wi through a smooth lobe.
    [[nodiscard]] float pdf(const Vec3& wi) const;
    /// Choose a lobe with `u_lobe`, then a direction with `u`. Empty if the BSDF is black or
    /// the direction falls under the surface.
    [[nodiscard]] std::optional<BsdfSample> sample(float u_lobe, Vec2 u) const;

    /// True if some smooth lobe has weight (light sampling can help).
    [[nodiscard]] bool has_smooth_lobes() const { return !diffuse_.is_black() || !highlight_.is_black(); }
    [[nodiscard]] const SpecularLobes& specular() const { return specular_; }
    [[nodiscard]] const Vec3& normal() const { return n_; }

private:
    /// Lobe selection probabilities, summing to 1 (or all 0 for a black BSDF).
    struct LobeChoice {
        float diffuse = 0.0f, highlight = 0.0f, reflect = 0.0f, transmit = 0.0f;
    };
    [[nodiscard]] LobeChoice lobe_choice() const;
    [[nodiscard]] float pdf(const Vec3& wi, const LobeChoice& p) const;
    [[nodiscard]] float highlight_pdf(const Vec3& wi) const;

    Vec3 n_, ng_, wo_;
    Color diffuse_;    ///< (1−t)·kd·tex
    Color highlight_;  ///< (1−t)·ks
    float shininess_ = 0.0f;
    SpecularLobes specular_;
    /// Relative index across the surface for the transmitted direction (eta_to/eta_from).
    float eta_ = 1.0f;
};

}  // namespace glint
