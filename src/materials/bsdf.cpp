#include "glint/materials/bsdf.h"

#include "glint/materials/microfacet.h"
#include "glint/materials/optics.h"
#include "glint/math/constants.h"
#include "glint/math/frame.h"
#include "glint/sampling/warp.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

float average(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }

/// Local (x, y, z) → world with z along n.
Vec3 around_normal(const Vec3& local, const Vec3& n) {
    Vec3 b1, b2;
    orthonormal_basis(n, b1, b2);
    return b1 * local.x + b2 * local.y + n * local.z;
}

}  // namespace

void Bsdf::add_glossy_lobes(const MaterialAtHit& at, bool fresnel_mirror, float t, Interface media) {
    const bool conductor = t < 1.0f && !at.reflectivity.is_black();
    // Equal indices stay with the delta glass (the constructor): refraction does not bend.
    const bool dielectric = t > 0.0f && media.eta_from != media.eta_to;
    if (!conductor && !dielectric) return;
    const float alpha = roughness_to_alpha(at.roughness);
    const TrowbridgeReitz ggx(alpha, alpha);
    GlossyLobes& g = glossy_.emplace();
    orthonormal_basis(n_, g.b1, g.b2);
    g.wo_local = to_local(wo_);
    if (conductor) {
        g.conductor = GlossyConductor(ggx, at.reflectivity, fresnel_mirror);
        g.conductor_scale = 1.0f - t;
    }
    if (dielectric) {
        g.dielectric = RoughDielectric(ggx, media.eta_from, media.eta_to);
        g.dielectric_scale = t;
    }
}

float Bsdf::conductor_weight() const {
    // The conductor's reflectance where the microfacets face the normal: its albedo at low
    // roughness, and an overestimate at high roughness, where masking takes a share.
    if (!glossy_ || !(glossy_->conductor_scale > 0.0f)) return 0.0f;
    return average(glossy_->conductor.fresnel(glossy_->wo_local.z)) * glossy_->conductor_scale;
}

Bsdf::LobeChoice Bsdf::lobe_choice() const {
    // In proportion to an estimate of each lobe's albedo; any positive choice is unbiased.
    // The Blinn-Phong lobe's albedo falls roughly as 8/(s+2) for large exponents. Computed
    // on demand: the Whitted integrator never samples, and pays nothing for it.
    const float w_diffuse = average(diffuse_);
    const float w_highlight = average(highlight_) * std::min(1.0f, 8.0f / (shininess_ + 2.0f));
    const float w_reflect = average(specular_.reflection);
    const float w_transmit = specular_.transmission;
    const float w_conductor = conductor_weight();
    const float w_dielectric = glossy_ ? glossy_->dielectric_scale : 0.0f;
    // The glossy weights are added last: 0 for a material without them, which leaves the sum,
    // and so the choice, exactly what it was before they existed.
    const float total = w_diffuse + w_highlight + w_reflect + w_transmit + w_conductor + w_dielectric;
    if (!(total > 0.0f)) return {};
    return {w_diffuse / total,    w_highlight / total, w_conductor / total,
            w_dielectric / total, w_reflect / total,   w_transmit / total};
}

Bsdf::LobeChoice Bsdf::glossy_choice() const {
    const float w_conductor = conductor_weight();
    const float w_dielectric = glossy_ ? glossy_->dielectric_scale : 0.0f;
    const float total = w_conductor + w_dielectric;
    if (!(total > 0.0f)) return {};
    LobeChoice p;
    p.conductor = w_conductor / total;
    p.dielectric = w_dielectric / total;
    return p;
}

float Bsdf::highlight_pdf(const Vec3& wi) const {
    // Half-vector density (s+1)/2π·cos^s θh, times the Jacobian 1/(4 wo·h) of reflection
    // (Walter et al. 2007, eq. 14).
    const Vec3 half = wi + wo_;
    if (!(dot(half, half) > 0.0f)) return 0.0f;
    const Vec3 h = normalize(half);
    const float wo_h = dot(wo_, h);
    if (wo_h <= 0.0f) return 0.0f;
    return phong_lobe_pdf(dot(n_, h), shininess_) / (4.0f * wo_h);
}

Color Bsdf::eval_glossy(const Vec3& wi) const {
    if (!glossy_) return Color();
    const float cn = dot(n_, wi), cg = dot(ng_, wi);
    const bool above = cn > 0.0f && cg > 0.0f, below = cn < 0.0f && cg < 0.0f;
    if (!above && !below) return Color();
    const Vec3 wi_local = to_local(wi);
    Color f;
    const GlossyLobes& g = *glossy_;
    if (g.conductor_scale > 0.0f && above) f += g.conductor.eval(g.wo_local, wi_local) * g.conductor_scale;
    if (g.dielectric_scale > 0.0f) f += Color(g.dielectric.eval(g.wo_local, wi_local) * g.dielectric_scale);
    return f;
}

float Bsdf::glossy_density(const Vec3& wi, const LobeChoice& p) const {
    const Vec3 wi_local = to_local(wi);
    float density = 0.0f;
    if (p.conductor > 0.0f) density += p.conductor * glossy_->conductor.pdf(glossy_->wo_local, wi_local);
    if (p.dielectric > 0.0f) density += p.dielectric * glossy_->dielectric.pdf(glossy_->wo_local, wi_local);
    return density;
}

float Bsdf::pdf(const Vec3& wi) const { return pdf(wi, lobe_choice()); }

float Bsdf::glossy_pdf(const Vec3& wi) const { return pdf(wi, glossy_choice()); }

float Bsdf::pdf(const Vec3& wi, const LobeChoice& p) const {
    const float cn = dot(n_, wi), cg = dot(ng_, wi);
    if (cn < 0.0f && cg < 0.0f && p.dielectric > 0.0f) return glossy_density(wi, p);  // transmission
    if (cn <= 0.0f || cg <= 0.0f) return 0.0f;
    float density = 0.0f;
    if (p.diffuse > 0.0f) density += p.diffuse * cosine_hemisphere_pdf(cn);
    if (p.highlight > 0.0f) density += p.highlight * highlight_pdf(wi);
    if (p.conductor > 0.0f || p.dielectric > 0.0f) density += glossy_density(wi, p);
    return density;
}

std::optional<BsdfSample> Bsdf::sample(float u_lobe, Vec2 u) const { return sample(u_lobe, u, lobe_choice(), false); }

std::optional<BsdfSample> Bsdf::sample_glossy(float u_lobe, Vec2 u) const {
    return sample(u_lobe, u, glossy_choice(), true);
}

std::optional<BsdfSample> Bsdf::sample(float u_lobe, Vec2 u, const LobeChoice& p, bool glossy_only) const {
    BsdfSample s;
    const float smooth_end = p.diffuse + p.highlight;
    const float conductor_end = smooth_end + p.conductor;
    const float glossy_end = conductor_end + p.dielectric;
    if (u_lobe < glossy_end) {
        if (u_lobe < p.diffuse) {
            s.wi = around_normal(sample_cosine_hemisphere(u), n_);
        } else if (u_lobe < smooth_end) {
            const Vec3 h = around_normal(sample_phong_lobe(u, shininess_), n_);
            s.wi = reflect(-wo_, h);
        } else if (u_lobe < conductor_end) {
            const std::optional<Vec3> wi = glossy_->conductor.sample(glossy_->wo_local, u);
            if (!wi) return std::nullopt;
            s.wi = to_world(*wi);
        } else {
            // What is left of u_lobe past the lobe's start is a fresh uniform number: it
            // chooses between the dielectric's reflection and refraction.
            const float u_choice = std::min((u_lobe - conductor_end) / p.dielectric, 0x1.fffffep-1f);
            const std::optional<Vec3> wi = glossy_->dielectric.sample(glossy_->wo_local, u_choice, u);
            if (!wi) return std::nullopt;
            s.wi = to_world(*wi);
        }
        s.pdf = pdf(s.wi, p);
        if (!(s.pdf > 0.0f)) return std::nullopt;
        const float cos_theta = dot(n_, s.wi);
        s.weight = (glossy_only ? eval_glossy(s.wi) : eval(s.wi)) * (std::abs(cos_theta) / s.pdf);
        s.flags = cos_theta < 0.0f ? kBsdfTransmission : kBsdfReflection;
        return s;
    }
    if (u_lobe < glossy_end + p.reflect) {
        s.wi = specular_.reflected;
        s.pdf = p.reflect;
        s.weight = specular_.reflection / p.reflect;
        s.flags = kBsdfReflection | kBsdfDelta;
        return s;
    }
    if (p.transmit > 0.0f && specular_.refracted) {
        s.wi = *specular_.refracted;
        s.pdf = p.transmit;
        // Radiance is compressed by (η_from/η_to)² on crossing into a denser medium (Veach
        // 1997, §5.2): the 1/η² of pbrt-v4's DielectricBxDF in radiance mode.
        s.weight = Color(specular_.transmission / (p.transmit * eta_ * eta_));
        s.flags = kBsdfTransmission | kBsdfDelta;
        return s;
    }
    return std::nullopt;
}

}  // namespace glint
