#include "glint/materials/microfacet_lobes.h"

#include "glint/materials/optics.h"

#include <algorithm>
#include <cmath>

namespace glint {

// ---- GlossyConductor --------------------------------------------------------------------

Color GlossyConductor::fresnel(float cos_theta) const {
    if (!schlick_) return kr_;
    // Schlick with a coloured F0 (metals), as the delta mirror: F0 + (1 − F0)(1 − cos θ)^5.
    const float c = 1.0f - std::clamp(cos_theta, 0.0f, 1.0f);
    const float c5 = c * c * c * c * c;
    return kr_ + (Color(1.0f) - kr_) * c5;
}

Color GlossyConductor::eval(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return Color();
    const Vec3 half = wo + wi;
    if (!(dot(half, half) > 0.0f)) return Color();
    const Vec3 wm = normalize(half);
    const float d_g = distribution_.D(wm) * distribution_.G(wo, wi);
    return fresnel(dot(wo, wm)) * (d_g / (4.0f * wo.z * wi.z));
}

float GlossyConductor::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const Vec3 half = wo + wi;
    if (!(dot(half, half) > 0.0f)) return 0.0f;
    const Vec3 wm = normalize(half);
    return distribution_.pdf(wo, wm) / (4.0f * dot(wo, wm));
}

std::optional<Vec3> GlossyConductor::sample(const Vec3& wo, Vec2 u) const {
    if (wo.z <= 0.0f) return std::nullopt;
    const Vec3 wi = reflect(-wo, distribution_.sample_wm(wo, u));
    if (wi.z <= 0.0f) return std::nullopt;
    return wi;
}

// ---- RoughDielectric --------------------------------------------------------------------

std::optional<Vec3> RoughDielectric::half_vector(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0.0f || wi.z == 0.0f) return std::nullopt;
    const float eta = wi.z > 0.0f ? 1.0f : eta_to_ / eta_from_;
    const Vec3 h = wo + wi * eta;
    if (!(dot(h, h) > 0.0f)) return std::nullopt;
    Vec3 wm = normalize(h);
    if (wm.z < 0.0f) wm = -wm;
    // Light meets a microfacet only from its front on both sides (Walter et al. 2007, §5.2).
    if (dot(wm, wi) * wi.z <= 0.0f || dot(wm, wo) <= 0.0f) return std::nullopt;
    return wm;
}

float RoughDielectric::fresnel(const Vec3& wo, const Vec3& wm) const {
    return fresnel_schlick(-wo, wm, eta_from_, eta_to_);
}

float RoughDielectric::eval(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Vec3> wm = half_vector(wo, wi);
    if (!wm) return 0.0f;
    const float f = fresnel(wo, *wm);
    const float d_g = distribution_.D(*wm) * distribution_.G(wo, wi);
    if (wi.z > 0.0f) return f * d_g / (4.0f * wo.z * wi.z);
    const float eta = eta_to_ / eta_from_;
    const float wi_wm = dot(wi, *wm), wo_wm = dot(wo, *wm);
    const float sum = eta * wi_wm + wo_wm;
    return (1.0f - f) * d_g * std::abs(wi_wm * wo_wm / (wo.z * wi.z * sum * sum));
}

float RoughDielectric::pdf(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Vec3> wm = half_vector(wo, wi);
    if (!wm) return 0.0f;
    const float f = fresnel(wo, *wm);
    const float visible = distribution_.pdf(wo, *wm);
    if (wi.z > 0.0f) return f * visible / (4.0f * dot(wo, *wm));
    const float eta = eta_to_ / eta_from_;
    const float wi_wm = dot(wi, *wm);
    const float sum = eta * wi_wm + dot(wo, *wm);
    return (1.0f - f) * visible * eta * eta * std::abs(wi_wm) / (sum * sum);
}

std::optional<Vec3> RoughDielectric::sample(const Vec3& wo, float u_choice, Vec2 u) const {
    if (wo.z <= 0.0f) return std::nullopt;
    const Vec3 wm = distribution_.sample_wm(wo, u);
    // Reflect with probability F, refract with 1 − F: the split the microfacet's Fresnel
    // term gives the energy, so that the weights stay near G/G1.
    if (u_choice < fresnel(wo, wm)) {
        const Vec3 wi = reflect(-wo, wm);
        if (wi.z <= 0.0f) return std::nullopt;
        return wi;
    }
    const std::optional<Vec3> wi = refract(-wo, wm, eta_from_, eta_to_);
    if (!wi || wi->z >= 0.0f) return std::nullopt;
    return normalize(*wi);
}

}  // namespace glint
