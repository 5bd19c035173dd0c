// The GGX distribution and the glossy lobes built on it: normalisation of D and of the
// visible normals, chi-square tests of every sampler against its density (tests/chi2.h),
// white furnaces, and the limit roughness → 0 against the delta lobes.

#include "bsdf_at_hit.h"
#include "chi2.h"

#include "glint/materials/bsdf.h"
#include "glint/materials/microfacet.h"
#include "glint/materials/optics.h"
#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>

using namespace glint;

using glint_test::bsdf_of;
using glint_test::from_polar;
using glint_test::kUp;

namespace {

// The chi-square tests below form one family (Šidák-corrected to 1% in all).
constexpr int kMicrofacetChi2Tests = 22;

/// ∫ f dω over the directions with cos θ in [z0, z1], in (cos θ, φ) where dω = d(cos θ) dφ.
double integrate_band(const std::function<double(const Vec3&)>& f, double z0, double z1) {
    return chi2_detail::integrate_2d(
        [&](double c, double phi) {
            const double s = std::sqrt(std::max(0.0, (1.0 - c) * (1.0 + c)));
            return f(Vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c)));
        },
        z0, z1, 0.0, 2.0 * std::numbers::pi, 1e-5, 16);
}

struct Alphas {
    float x, y;
};
std::ostream& operator<<(std::ostream& os, const Alphas& a) { return os << "alpha (" << a.x << ", " << a.y << ")"; }

Material rough_metal(float roughness, const Color& kr = Color(1.0f), bool schlick = false) {
    Material m;
    m.diffuse = Color(0.0f);
    m.reflectivity = kr;
    m.fresnel_mirror = schlick;
    m.roughness = roughness;
    return m;
}

Material rough_glass(float roughness, float ior = 1.5f) {
    Material m;
    m.diffuse = Color(0.0f);
    m.transparency = 1.0f;
    m.ior = ior;
    m.roughness = roughness;
    return m;
}

/// chi-square of Bsdf::sample (or sample_glossy) against pdf (glossy_pdf) over the whole
/// sphere; u_lobe from its own stream, as an integrator draws it.
Chi2Result sphere_chi2(const Bsdf& bsdf, bool glossy_only, uint64_t seed) {
    pcg32 lobe_rng(seed, 99);
    auto sample = [&](Vec2 u) -> std::optional<Vec3> {
        const float u_lobe = chi2_detail::uniform_float(lobe_rng);
        const std::optional<BsdfSample> s = glossy_only ? bsdf.sample_glossy(u_lobe, u) : bsdf.sample(u_lobe, u);
        if (!s || (s->flags & kBsdfDelta)) return std::nullopt;
        return s->wi;
    };
    auto pdf = [&](const Vec3& w) { return double(glossy_only ? bsdf.glossy_pdf(w) : bsdf.pdf(w)); };
    return chi2_spherical_grid(sample, pdf, {20, 24, -1.0, 1.0}, {300'000, seed, 0.01, kMicrofacetChi2Tests});
}

/// Mean and standard error of the red channel of `samples` Bsdf::sample weights (0 where
/// it returns nothing); transmitted weights are multiplied by `transmission_scale`.
struct AlbedoEstimate {
    double mean = 0.0, stderr_ = 0.0;
};
AlbedoEstimate sampled_albedo(const Bsdf& bsdf, int samples, float transmission_scale = 1.0f, uint64_t seed = 3) {
    pcg32 rng(seed);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < samples; ++i) {
        const float u_lobe = chi2_detail::uniform_float(rng);
        const Vec2 u(chi2_detail::uniform_float(rng), chi2_detail::uniform_float(rng));
        double w = 0.0;
        if (const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u))
            w = s->weight.r * ((s->flags & kBsdfTransmission) ? transmission_scale : 1.0f);
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / samples;
    return {mean, std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples)};
}

}  // namespace

// ---- The distribution --------------------------------------------------------------------

TEST(TrowbridgeReitz, ProjectedNormalDensityIntegratesToOne) {
    // ∫ D(wm) cos θm dωm = 1: the microfacets' projected area is the macrosurface's.
    for (const Alphas a : {Alphas{0.05f, 0.05f}, Alphas{0.3f, 0.3f}, Alphas{1.0f, 1.0f}, Alphas{0.1f, 0.5f}}) {
        const TrowbridgeReitz d(a.x, a.y);
        const double total = integrate_band([&](const Vec3& wm) { return double(d.D(wm)) * wm.z; }, 0.0, 1.0);
        EXPECT_NEAR(total, 1.0, 1e-3) << a;
    }
}

TEST(TrowbridgeReitz, VisibleNormalDensityIntegratesToOne) {
    int checked = 0;
    for (const Alphas a : {Alphas{0.2f, 0.2f}, Alphas{0.8f, 0.8f}, Alphas{0.1f, 0.6f}}) {
        const TrowbridgeReitz d(a.x, a.y);
        // Also from under the surface (the mirror image's visible normals) and near grazing.
        for (const Vec3 w :
             {from_polar(0.0f), from_polar(45.0f, 30.0f), from_polar(85.0f, 120.0f), from_polar(130.0f, 200.0f)}) {
            const double total = integrate_band([&](const Vec3& wm) { return double(d.D(w, wm)); }, 0.0, 1.0);
            EXPECT_NEAR(total, 1.0, 2e-3) << a << ", w = " << w;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 12);
}

TEST(TrowbridgeReitz, SmithMaskingMatchesItsClosedFormAndIsOneAtTheNormal) {
    const TrowbridgeReitz d(0.4f, 0.4f);
    EXPECT_FLOAT_EQ(d.G1(kUp), 1.0f);
    EXPECT_EQ(d.G1(Vec3(1.0f, 0.0f, 0.0f)), 0.0f) << "a grazing direction sees no microfacet";
    // Isotropic Smith-GGX, Walter et al. 2007 eq. 34: G1 = 2 / (1 + √(1 + α² tan²θ)).
    const float theta = radians(60.0f), alpha = 0.4f;
    const float expected = 2.0f / (1.0f + std::sqrt(1.0f + alpha * alpha * std::tan(theta) * std::tan(theta)));
    EXPECT_NEAR(d.G1(from_polar(60.0f, 77.0f)), expected, 1e-6f);
    // Height-correlated: G = 1/(1 + Λo + Λi) ≥ G1(wo)·G1(wi) (Heitz 2014, §6).
    const Vec3 wo = from_polar(60.0f), wi = from_polar(40.0f, 180.0f);
    EXPECT_GE(d.G(wo, wi), d.G1(wo) * d.G1(wi));
    EXPECT_LE(d.G(wo, wi), std::min(d.G1(wo), d.G1(wi)));
}

TEST(MicrofacetChi2, VisibleNormalSamplesFollowTheirDensity) {
    const struct {
        Alphas alpha;
        double cos_min;  // a band that holds the lobe, so that its cells resolve it
    } cases[] = {{{0.2f, 0.2f}, 0.6}, {{0.6f, 0.6f}, 0.0}, {{1.0f, 1.0f}, 0.0}, {{0.15f, 0.6f}, 0.0}};
    for (const auto& c : cases) {
        const TrowbridgeReitz d(c.alpha.x, c.alpha.y);
        for (const Vec3 w : {from_polar(0.0f), from_polar(50.0f, 40.0f), from_polar(85.0f, 250.0f)}) {
            const Chi2Result r =
                chi2_spherical_grid([&](Vec2 u) { return std::optional<Vec3>(d.sample_wm(w, u)); },
                                    [&](const Vec3& wm) { return double(d.pdf(w, wm)); }, {12, 24, c.cos_min, 1.0},
                                    {300'000, 11, 0.01, kMicrofacetChi2Tests});
            EXPECT_TRUE(r.passed) << c.alpha << ", w = " << w << "\n" << r.report;
        }
    }
}

// ---- The glossy lobes through Bsdf -------------------------------------------------------

TEST(MicrofacetChi2, GlossyConductorSamplesFollowThePdf) {
    for (const float roughness : {0.3f, 0.7f}) {
        for (const float theta : {20.0f, 70.0f}) {
            const Bsdf bsdf =
                bsdf_of(rough_metal(roughness, Color(0.9f, 0.6f, 0.3f), true), kUp, kUp, from_polar(theta), {});
            ASSERT_TRUE(bsdf.has_glossy_lobes());
            const Chi2Result r = sphere_chi2(bsdf, false, 21);
            EXPECT_TRUE(r.passed) << "roughness " << roughness << ", θo = " << theta << "\n" << r.report;
        }
    }
    // Mixed with a Lambert lobe: the one-sample mixture, and the glossy lobe alone.
    Material m = rough_metal(0.4f, Color(0.5f), true);
    m.diffuse = Color(0.4f);
    const Bsdf mixed = bsdf_of(m, kUp, kUp, from_polar(45.0f), {});
    for (const bool glossy_only : {false, true}) {
        const Chi2Result r = sphere_chi2(mixed, glossy_only, 22);
        EXPECT_TRUE(r.passed) << (glossy_only ? "glossy lobe alone" : "mixture") << "\n" << r.report;
    }
}

TEST(MicrofacetChi2, RoughDielectricSamplesFollowThePdfEnteringAndLeaving) {
    int transmitted = 0;
    // Leaving at 60° lies past the critical angle (41.8°) of the smooth interface. (Entering
    // at low roughness is left out for time: the pdf jumps where the generalised half-vector
    // crosses the horizon, and integrating the cells along that curve takes seconds.)
    const struct {
        float roughness, theta;
        Interface media;
    } cases[] = {{0.5f, 45.0f, {1.0f, 1.5f}},
                 {0.6f, 30.0f, {1.0f, 1.5f}},
                 {0.3f, 30.0f, {1.5f, 1.0f}},
                 {0.3f, 60.0f, {1.5f, 1.0f}}};
    for (const auto& [roughness, theta, media] : cases) {
        const Bsdf bsdf = bsdf_of(rough_glass(roughness), kUp, kUp, from_polar(theta, 10.0f), media);
        const Chi2Result r = sphere_chi2(bsdf, false, 31);
        EXPECT_TRUE(r.passed) << "roughness " << roughness << ", η " << media.eta_from << " → " << media.eta_to
                              << ", θo = " << theta << "\n"
                              << r.report;
        const auto s = bsdf.sample(0.99f, Vec2(0.5f, 0.5f));
        transmitted += s && (s->flags & kBsdfTransmission) ? 1 : 0;
    }
    EXPECT_GT(transmitted, 0) << "the grids must have seen refracted samples";
}

TEST(GlossyLobes, SampleWeightIsEvalTimesCosineOverPdf) {
    Material mixed = rough_metal(0.35f, Color(0.8f, 0.5f, 0.2f), true);
    mixed.diffuse = Color(0.3f);
    mixed.transparency = 0.4f;
    mixed.roughness = 0.35f;
    const Vec3 wo = from_polar(35.0f, 60.0f);
    int checked = 0, transmitted = 0;
    for (const Interface media : {Interface{1.0f, 1.5f}, Interface{1.5f, 1.0f}}) {
        const Bsdf bsdf = bsdf_of(mixed, kUp, kUp, wo, media);
        for (int i = 0; i < 32; ++i)
            for (int j = 0; j < 32; ++j) {
                const Vec2 u((i + 0.5f) / 32.0f, (j + 0.5f) / 32.0f);
                const float u_lobe = ((i * 32 + j) * 0.618034f) - std::floor((i * 32 + j) * 0.618034f);
                for (const bool glossy_only : {false, true}) {
                    const auto s = glossy_only ? bsdf.sample_glossy(u_lobe, u) : bsdf.sample(u_lobe, u);
                    if (!s) continue;
                    const float pdf = glossy_only ? bsdf.glossy_pdf(s->wi) : bsdf.pdf(s->wi);
                    const Color f = glossy_only ? bsdf.eval_glossy(s->wi) : bsdf.eval(s->wi);
                    const float cos_theta = dot(kUp, s->wi);
                    EXPECT_FALSE(s->flags & kBsdfDelta);
                    EXPECT_EQ((s->flags & kBsdfTransmission) != 0, cos_theta < 0.0f);
                    EXPECT_NEAR(s->pdf, pdf, 1e-4f * pdf);
                    for (int c = 0; c < 3; ++c) {
                        const float expected = f[c] * std::abs(cos_theta) / pdf;
                        EXPECT_NEAR(s->weight[c], expected, 1e-4f * expected + 1e-7f) << s->wi;
                    }
                    ++checked;
                    transmitted += cos_theta < 0.0f ? 1 : 0;
                }
            }
    }
    EXPECT_GT(checked, 3000);
    EXPECT_GT(transmitted, 100);
}

TEST(GlossyLobes, EvalPartsSplitOffTheGlossyShare) {
    // The Whitted integrator weighs eval_parts' glossy share against its glossy samples: it
    // must be eval_glossy bit for bit, on both sides, and nothing for a material without it.
    Material mixed = rough_metal(0.35f, Color(0.8f, 0.5f, 0.2f), true);
    mixed.diffuse = Color(0.3f);
    mixed.transparency = 0.4f;
    Material matte;
    matte.diffuse = Color(0.5f);
    const Vec3 wo = from_polar(35.0f, 60.0f);
    int above = 0, below = 0;
    for (const Interface media : {Interface{1.0f, 1.5f}, Interface{1.5f, 1.0f}}) {
        const Bsdf bsdf = bsdf_of(mixed, kUp, kUp, wo, media);
        const Bsdf plain = bsdf_of(matte, kUp, kUp, wo, media);
        for (int i = 0; i < 36; ++i)
            for (int j = 0; j < 12; ++j) {
                const Vec3 wi = from_polar(2.5f + 5.0f * float(i), 30.0f * float(j));
                const Bsdf::EvalParts parts = bsdf.eval_parts(wi);
                const Color glossy = bsdf.eval_glossy(wi);
                for (int c = 0; c < 3; ++c) EXPECT_EQ(parts.glossy[c], glossy[c]) << wi;
                if (wi.z < 0.0f) {
                    for (int c = 0; c < 3; ++c) EXPECT_EQ(parts.all[c], glossy[c]) << wi;
                    below += glossy.is_black() ? 0 : 1;
                } else {
                    // The rest is the Lambert lobe, its diffuse weighted by 1 − transparency.
                    EXPECT_NEAR(parts.all.r - parts.glossy.r, 0.3f * (1.0f - 0.4f) * kInvPi, 1e-5f) << wi;
                    above += glossy.is_black() ? 0 : 1;
                }
                EXPECT_TRUE(plain.eval_parts(wi).glossy.is_black());
            }
    }
    EXPECT_GT(above, 100);
    EXPECT_GT(below, 100);
}

TEST(GlossyFurnace, WhiteRoughConductorReflectsAtMostEverything) {
    // F = 1 and no other lobe: the directional albedo ∫ f cos θi dωi is what masking leaves,
    // at most 1, and close to 1 for a smooth surface. Estimated by importance sampling with
    // 10^5 samples; a bound of 4 standard errors.
    constexpr int kSamples = 100'000;
    for (const float roughness : {0.05f, 0.2f, 0.5f, 1.0f}) {
        for (const float theta : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
            const Bsdf bsdf = bsdf_of(rough_metal(roughness), kUp, kUp, from_polar(theta), {});
            const AlbedoEstimate e = sampled_albedo(bsdf, kSamples);
            EXPECT_LE(e.mean, 1.0 + 4.0 * e.stderr_ + 1e-6) << "roughness " << roughness << ", θo = " << theta;
            if (roughness <= 0.05f && theta <= 60.0f) {
                EXPECT_GT(e.mean, 0.99) << "roughness " << roughness << ", θo = " << theta;
            }
            EXPECT_GT(e.mean, 0.25) << "roughness " << roughness << ", θo = " << theta;  // 0.31 at r = 1, θo = 0
        }
    }
}

TEST(GlossyFurnace, SampledAlbedoAgreesWithUniformIntegrationOfEval) {
    // The same integral without the sampler: ∫ f |cos θi| dωi with uniform directions over the
    // sphere, so that a pdf and an eval that agree with each other but not with the BRDF's
    // normalisation cannot pass. Rough enough that uniform sampling sees the lobe.
    constexpr int kSamples = 200'000;
    const Bsdf metal = bsdf_of(rough_metal(0.7f), kUp, kUp, from_polar(40.0f), {});
    const Bsdf glass = bsdf_of(rough_glass(0.7f), kUp, kUp, from_polar(40.0f), {1.0f, 1.5f});
    for (const Bsdf* bsdf : {&metal, &glass}) {
        pcg32 rng(17);
        double sum = 0.0, sum2 = 0.0;
        for (int i = 0; i < kSamples; ++i) {
            const Vec3 wi =
                sample_uniform_sphere(Vec2(chi2_detail::uniform_float(rng), chi2_detail::uniform_float(rng)));
            const double v = bsdf->eval(wi).r * std::abs(wi.z) / uniform_sphere_pdf();
            sum += v;
            sum2 += v * v;
        }
        const double mean = sum / kSamples;
        const double se = std::sqrt(std::max(0.0, sum2 / kSamples - mean * mean) / kSamples);
        const AlbedoEstimate sampled = sampled_albedo(*bsdf, kSamples);
        EXPECT_NEAR(sampled.mean, mean, 5.0 * std::sqrt(se * se + sampled.stderr_ * sampled.stderr_))
            << (bsdf == &metal ? "metal" : "glass");
    }
}

TEST(GlossyFurnace, RoughDielectricReflectsAndTransmitsAtMostEverything) {
    // Reflection plus transmission with the transmitted radiance's 1/η² undone: at most 1.
    constexpr int kSamples = 100'000;
    for (const float roughness : {0.05f, 0.3f, 1.0f}) {
        for (const Interface media : {Interface{1.0f, 1.5f}, Interface{1.5f, 1.0f}}) {
            const float eta = media.eta_to / media.eta_from;
            for (const float theta : {0.0f, 30.0f, 60.0f, 85.0f}) {
                const Bsdf bsdf = bsdf_of(rough_glass(roughness), kUp, kUp, from_polar(theta), media);
                const AlbedoEstimate e = sampled_albedo(bsdf, kSamples, eta * eta);
                EXPECT_LE(e.mean, 1.0 + 4.0 * e.stderr_ + 1e-6)
                    << "roughness " << roughness << ", η = " << eta << ", θo = " << theta;
                if (roughness <= 0.05f && theta <= 30.0f) {
                    EXPECT_GT(e.mean, 0.98) << "roughness " << roughness << ", η = " << eta << ", θo = " << theta;
                }
            }
        }
    }
}

// ---- Roughness 0 and its neighbourhood ---------------------------------------------------

TEST(GlossyLobes, RoughnessZeroIsTheDeltaMirrorAndGlass) {
    // The delta weights from their formulas: (1 − t)·Schlick(F0 = kr) + t·F for the mirror
    // direction, t·(1 − F) for the refracted one, F = Schlick of the interface.
    Material m;
    m.diffuse = Color(0.0f);
    m.reflectivity = Color(0.9f, 0.6f, 0.3f);
    m.fresnel_mirror = true;
    m.transparency = 0.5f;
    m.ior = 1.5f;
    m.roughness = 0.0f;
    const Vec3 wo = from_polar(50.0f);
    const Bsdf bsdf = bsdf_of(m, kUp, kUp, wo, {1.0f, 1.5f});
    EXPECT_FALSE(bsdf.has_glossy_lobes());
    EXPECT_FALSE(bsdf.has_smooth_lobes());
    const float c5 = std::pow(1.0f - std::cos(radians(50.0f)), 5.0f);
    const float f = fresnel_schlick(-wo, kUp, 1.0f, 1.5f);
    const SpecularLobes& lobes = bsdf.specular();
    for (int c = 0; c < 3; ++c) {
        const float kr = m.reflectivity[c];
        EXPECT_NEAR(lobes.reflection[c], 0.5f * (kr + (1.0f - kr) * c5) + 0.5f * f, 1e-6f) << c;
    }
    EXPECT_NEAR(lobes.transmission, 0.5f * (1.0f - f), 1e-6f);
    EXPECT_NEAR(dot(lobes.reflected, Vec3(-wo.x, -wo.y, wo.z)), 1.0f, 1e-6f);
    ASSERT_TRUE(lobes.refracted);
    // Nothing with a density: eval and pdf are 0 in the mirror direction and under the surface.
    EXPECT_TRUE(bsdf.eval(lobes.reflected).is_black());
    EXPECT_EQ(bsdf.pdf(*lobes.refracted), 0.0f);
    EXPECT_FALSE(bsdf.may_reflect(*lobes.refracted));
    for (const float u_lobe : {0.1f, 0.9f}) {
        const auto s = bsdf.sample(u_lobe, Vec2(0.3f, 0.7f));
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->flags & kBsdfDelta);
    }
}

TEST(GlossyLobes, SmallRoughnessApproachesTheDeltas) {
    // At roughness 0.02 (alpha 4e-4) the glossy lobes sample (almost all) within a degree of
    // the delta directions and split reflection and refraction by the delta's Fresnel weight, entering
    // and leaving: the microfacet code uses the delta code's conventions.
    for (const Interface media : {Interface{1.0f, 1.5f}, Interface{1.5f, 1.0f}}) {
        const Vec3 wo = from_polar(30.0f, 45.0f);
        const Bsdf rough = bsdf_of(rough_glass(0.02f), kUp, kUp, wo, media);
        const Bsdf smooth = bsdf_of(rough_glass(0.0f), kUp, kUp, wo, media);
        ASSERT_TRUE(smooth.specular().refracted);
        constexpr int kSamples = 20'000;
        pcg32 rng(5);
        int reflected = 0, within_a_degree = 0;
        for (int i = 0; i < kSamples; ++i) {
            const float u_lobe = chi2_detail::uniform_float(rng);
            const auto s = rough.sample(u_lobe, Vec2(chi2_detail::uniform_float(rng), chi2_detail::uniform_float(rng)));
            ASSERT_TRUE(s);
            const bool is_reflection = (s->flags & kBsdfTransmission) == 0;
            reflected += is_reflection ? 1 : 0;
            const Vec3 delta = is_reflection ? smooth.specular().reflected : *smooth.specular().refracted;
            within_a_degree += dot(s->wi, normalize(delta)) > std::cos(radians(1.0f)) ? 1 : 0;
        }
        // GGX has long tails: P(tan θm > x) = α²/(α² + x²) puts ~0.2% of the normals half a
        // degree off at this alpha.
        EXPECT_GT(within_a_degree, 0.98 * kSamples) << "η " << media.eta_from << " → " << media.eta_to;
        const double p = smooth.specular().reflection.r;  // F of the delta glass (t = 1)
        EXPECT_NEAR(double(reflected) / kSamples, p, 4.0 * std::sqrt(p * (1.0 - p) / kSamples))
            << "η " << media.eta_from << " → " << media.eta_to;
    }
}

TEST(GlossyLobes, EqualIndicesKeepTheDeltaPassThrough) {
    // A dielectric of the surrounding index does not bend rays at any roughness (glTF's
    // BLEND layer): it stays the delta, rather than a lobe whose half-vector is undefined.
    const Bsdf bsdf = bsdf_of(rough_glass(0.5f, 1.0f), kUp, kUp, from_polar(30.0f), {1.0f, 1.0f});
    EXPECT_FALSE(bsdf.has_glossy_lobes());
    ASSERT_TRUE(bsdf.specular().refracted);
    EXPECT_NEAR(dot(*bsdf.specular().refracted, -from_polar(30.0f)), 1.0f, 1e-6f);
}

TEST(GlossyLobes, TransmissionLiesUnderBothNormalsOnly) {
    const Bsdf glass = bsdf_of(rough_glass(0.4f), kUp, kUp, from_polar(20.0f), {1.0f, 1.5f});
    const Vec3 down = from_polar(170.0f, 180.0f);
    EXPECT_TRUE(glass.may_reflect(down));
    EXPECT_GT(glass.eval(down).r, 0.0f);
    EXPECT_GT(glass.pdf(down), 0.0f);
    // A shading normal tilted 30° from the geometric one: a direction under the shading
    // normal but above the true surface (and the reverse) takes no lobe at all.
    const Vec3 n = from_polar(30.0f);
    const Bsdf tilted = bsdf_of(rough_glass(0.4f), n, kUp, kUp, {1.0f, 1.5f});
    const Vec3 between = normalize(Vec3(-1.0f, 0.0f, 0.3f));
    ASSERT_LT(dot(n, between), 0.0f);
    ASSERT_GT(dot(kUp, between), 0.0f);
    EXPECT_FALSE(tilted.may_reflect(between));
    EXPECT_TRUE(tilted.eval(between).is_black());
    EXPECT_EQ(tilted.pdf(between), 0.0f);
    // The reverse: above the shading normal, under the true surface, 47° from the mirror
    // direction (0.866, 0, 0.5), where the reflection lobe itself is far from zero.
    const Vec3 under = normalize(Vec3(1.0f, 0.0f, -0.3f));
    ASSERT_GT(dot(n, under), 0.0f);
    ASSERT_LT(dot(kUp, under), 0.0f);
    const Bsdf tilted_metal = bsdf_of(rough_metal(0.6f), n, kUp, kUp, {});
    const Bsdf untilted_metal = bsdf_of(rough_metal(0.6f), n, n, kUp, {});  // the same lobe, true normal n
    ASSERT_GT(untilted_metal.eval(under).r, 0.0f);
    ASSERT_GT(untilted_metal.pdf(under), 0.0f);
    for (const Bsdf* bsdf : {&tilted, &tilted_metal}) {
        EXPECT_FALSE(bsdf->may_reflect(under));
        EXPECT_TRUE(bsdf->eval(under).is_black());
        EXPECT_TRUE(bsdf->eval_glossy(under).is_black());
        EXPECT_EQ(bsdf->pdf(under), 0.0f);
        EXPECT_EQ(bsdf->glossy_pdf(under), 0.0f);
    }
    // An opaque rough metal never scatters under the surface.
    const Bsdf metal = bsdf_of(rough_metal(0.4f), kUp, kUp, from_polar(20.0f), {});
    EXPECT_FALSE(metal.may_reflect(down));
    EXPECT_TRUE(metal.eval(down).is_black());
}
