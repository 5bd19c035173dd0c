#include "glint/materials/bsdf.h"

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
Vec3 to_world(const Vec3& local, const Vec3& n) {
    Vec3 b1, b2;
    orthonormal_basis(n, b1, b2);
    return b1 * local.x + b2 * local.y + n * local.z;
}

}  // namespace

Bsdf::LobeChoice Bsdf::lobe_choice() const {
    // In proportion to an estimate of each lobe's albedo; any positive choice is unbiased.
    // The Blinn-Phong lobe's albedo falls roughly as 8/(s+2) for large exponents. Computed
    // on demand: the Whitted integrator never samples, and pays nothing for it.
    const float w_diffuse = average(diffuse_);
    const float w_highlight = average(highlight_) * std::min(1.0f, 8.0f / (shininess_ + 2.0f));
    const float w_reflect = average(specular_.reflection);
    const float w_transmit = specular_.transmission;
    const float total = w_diffuse + w_highlight + w_reflect + w_transmit;
    if (!(total > 0.0f)) return {};
    return {w_diffuse / total, w_highlight / total, w_reflect / total, w_transmit / total};
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

float Bsdf::pdf(const Vec3& wi) const { return pdf(wi, lobe_choice()); }

float Bsdf::pdf(const Vec3& wi, const LobeChoice& p) const {
    if (dot(n_, wi) <= 0.0f || dot(ng_, wi) <= 0.0f) return 0.0f;
    float density = 0.0f;
    if (p.diffuse > 0.0f) density += p.diffuse * cosine_hemisphere_pdf(dot(n_, wi));
    if (p.highlight > 0.0f) density += p.highlight * highlight_pdf(wi);
    return density;
}

std::optional<BsdfSample> Bsdf::sample(float u_lobe, Vec2 u) const {
    const LobeChoice p = lobe_choice();
    BsdfSample s;
    if (u_lobe < p.diffuse + p.highlight) {
        if (u_lobe < p.diffuse) {
            s.wi = to_world(sample_cosine_hemisphere(u), n_);
        } else {
            const Vec3 h = to_world(sample_phong_lobe(u, shininess_), n_);
            s.wi = reflect(-wo_, h);
        }
        s.pdf = pdf(s.wi, p);
        if (!(s.pdf > 0.0f)) return std::nullopt;
        s.weight = eval(s.wi) * (dot(n_, s.wi) / s.pdf);
        s.flags = kBsdfReflection;
        return s;
    }
    if (u_lobe < p.diffuse + p.highlight + p.reflect) {
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
