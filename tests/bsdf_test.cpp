// The BSDF seam: each lobe's sample() against its pdf (chi-square), delta lobe weights
// against Fresnel, and the Lambert lobe's albedo.

#include "bsdf_at_hit.h"
#include "chi2.h"

#include "glint/materials/bsdf.h"
#include "glint/materials/optics.h"
#include "glint/math/constants.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace glint;

using glint_test::bsdf_of;
using glint_test::from_polar;
using glint_test::kUp;

namespace {

/// chi-square of the smooth part: u_lobe is drawn from u's first coordinate's complement so
/// one uniform pair drives both the lobe choice and the direction, like an integrator would.
Chi2Result hemisphere_chi2(const Bsdf& bsdf, int test_count = 1, uint64_t seed = 7) {
    pcg32 lobe_rng(seed, 99);
    auto sample = [&](Vec2 u) -> std::optional<Vec3> {
        const float u_lobe = float(lobe_rng() >> 8) * 0x1p-24f;
        const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u);
        if (!s || (s->flags & kBsdfDelta)) return std::nullopt;
        return s->wi;
    };
    // Reflection lobes live on the upper hemisphere: resolve it finely (rejected samples and
    // any below the horizon go to the remainder cell, whose expectation is the missing mass).
    return chi2_spherical_grid(sample, [&](const Vec3& w) { return double(bsdf.pdf(w)); }, {12, 24, 0.0, 1.0},
                               {400'000, seed, 0.01, test_count});
}

Material lambert(float kd) {
    Material m;
    m.diffuse = Color(kd);
    return m;
}

}  // namespace

TEST(BsdfSampling, LambertMatchesItsPdf) {
    const Bsdf bsdf = bsdf_of(lambert(0.8f), kUp, kUp, from_polar(30.0f), {});
    const Chi2Result r = hemisphere_chi2(bsdf);
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(BsdfSampling, BlinnPhongLobeMatchesItsPdfAtSeveralExponentsAndAngles) {
    for (float shininess : {5.0f, 40.0f}) {
        for (float theta : {0.0f, 45.0f, 75.0f}) {
            Material m;
            m.diffuse = Color(0.0f);
            m.specular = Color(0.5f);
            m.shininess = shininess;
            const Bsdf bsdf = bsdf_of(m, kUp, kUp, from_polar(theta), {});
            const Chi2Result r = hemisphere_chi2(bsdf, 6);  // six tests: Šidák-corrected level
            EXPECT_TRUE(r.passed) << "s = " << shininess << ", θo = " << theta << "\n" << r.report;
        }
    }
}

TEST(BsdfSampling, MixtureOfLambertHighlightAndMirrorMatchesItsPdf) {
    Material m;
    m.diffuse = Color(0.4f, 0.3f, 0.2f);
    m.specular = Color(0.3f);
    m.shininess = 20.0f;
    m.reflectivity = Color(0.3f);  // a delta lobe: its samples are rejected from the smooth histogram
    const Bsdf bsdf = bsdf_of(m, kUp, kUp, from_polar(50.0f), {});
    const Chi2Result r = hemisphere_chi2(bsdf);
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(BsdfSampling, WhiteLambertReflectsEverything) {
    // Weight f·cosθ/pdf is exactly kd for cosine sampling: a furnace in one line.
    const Bsdf bsdf = bsdf_of(lambert(1.0f), kUp, kUp, from_polar(10.0f), {});
    for (float u : {0.1f, 0.5f, 0.9f}) {
        const auto s = bsdf.sample(0.5f, Vec2(u, 1.0f - u));
        ASSERT_TRUE(s);
        EXPECT_NEAR(s->weight.r, 1.0f, 1e-5f);
    }
}

TEST(BsdfSampling, NothingUnderTheTrueSurface) {
    // Shading normal tilted 30° away from the geometric one: directions under the true
    // surface are neither evaluated nor sampled.
    const Vec3 n = from_polar(30.0f);
    const Bsdf bsdf = bsdf_of(lambert(1.0f), n, kUp, kUp, {});
    const Vec3 below = normalize(Vec3(1.0f, 0.0f, -0.2f));
    ASSERT_GT(dot(n, below), 0.0f);
    EXPECT_TRUE(bsdf.eval(below).is_black());
    EXPECT_EQ(bsdf.pdf(below), 0.0f);
}

TEST(BsdfDelta, GlassSplitsBySchlickAndScalesTransmittedRadianceByEtaSquared) {
    Material glass;
    glass.diffuse = Color(0.0f);
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    const Vec3 wo = from_polar(40.0f);
    const Bsdf bsdf = bsdf_of(glass, kUp, kUp, wo, {1.0f, 1.5f});
    const float f = fresnel_schlick(-wo, kUp, 1.0f, 1.5f);
    EXPECT_NEAR(bsdf.specular().reflection.r, f, 1e-6f);
    EXPECT_NEAR(bsdf.specular().transmission, 1.0f - f, 1e-6f);
    const auto reflected = bsdf.sample(0.0f, Vec2(0.5f, 0.5f));
    const auto transmitted = bsdf.sample(0.999f, Vec2(0.5f, 0.5f));
    ASSERT_TRUE(reflected && transmitted);
    EXPECT_TRUE(reflected->flags & kBsdfDelta);
    EXPECT_TRUE(transmitted->flags & kBsdfTransmission);
    // Chosen with probability F and 1 − F: the weights are 1 and 1/η² (radiance compression).
    EXPECT_NEAR(reflected->weight.r, 1.0f, 1e-5f);
    EXPECT_NEAR(transmitted->weight.r, 1.0f / (1.5f * 1.5f), 1e-5f);
    EXPECT_NEAR(dot(transmitted->wi, *bsdf.specular().refracted), 1.0f, 1e-6f);
}

TEST(BsdfDelta, TotalInternalReflectionReflectsAll) {
    Material glass;
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    // Inside the glass at 60° (critical angle 41.8°).
    const Bsdf bsdf = bsdf_of(glass, kUp, kUp, from_polar(60.0f), {1.5f, 1.0f});
    EXPECT_FALSE(bsdf.specular().refracted);
    EXPECT_EQ(bsdf.specular().transmission, 0.0f);
    EXPECT_NEAR(bsdf.specular().reflection.r, 1.0f, 1e-6f);
}
