// Sampling routines against their densities: Pearson chi-square tests (tests/chi2.h) for
// every warp and for DiscreteDistribution, plus exact checks of domains, normalisation and
// edge cases. The harness itself is tested in chi2_test.cpp.

#include "chi2.h"
#include "glint/math/constants.h"
#include "glint/sampling/discrete_distribution.h"
#include "glint/sampling/warp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

using namespace glint;

namespace {

// Every chi-square test in this file is one member of a family of this many; with the Šidák
// correction the family rejects correct samplers with probability 1% in all (fixed seeds make
// the outcome reproducible, but a new seed must not be a coin toss).
constexpr int kChi2Tests = 15;

Chi2Options family_options(std::size_t samples) { return {samples, 1, 0.01, kChi2Tests}; }

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// u values on a 33×33 grid of [0, 1)², corners included: the places a warp divides by zero
// or takes the root of a negative number if anywhere.
std::vector<Vec2> grid_of_u() {
    std::vector<Vec2> us;
    for (int i = 0; i <= 32; ++i) {
        for (int j = 0; j <= 32; ++j)
            us.emplace_back(std::min(i / 32.0f, kOneMinusEpsilon), std::min(j / 32.0f, kOneMinusEpsilon));
    }
    return us;
}

// ∫ pdf dω over the whole sphere, in (cos θ, φ) where dω = d(cos θ) dφ.
double integrate_over_sphere(const std::function<double(const Vec3&)>& pdf) {
    return chi2_detail::integrate_2d(
        [&](double c, double phi) {
            const double s = std::sqrt(std::max(0.0, (1.0 - c) * (1.0 + c)));
            return pdf(Vec3(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
                            static_cast<float>(c)));
        },
        -1.0, 1.0, 0.0, 2.0 * std::numbers::pi, 1e-9);
}

float cone_pdf_at(const Vec3& w, float cos_theta_max) {
    return w.z >= cos_theta_max ? uniform_cone_pdf(cos_theta_max) : 0.0f;
}

}  // namespace

// ---- Exact properties --------------------------------------------------------------------

TEST(Warp, ConcentricDiskStaysInDiskAndMapsSquareEdgeToCircle) {
    for (const Vec2 u : grid_of_u()) {
        const Vec2 d = sample_uniform_disk_concentric(u);
        EXPECT_LE(d.x * d.x + d.y * d.y, 1.0f + 1e-6f) << u.x << ", " << u.y;
    }
    EXPECT_EQ(sample_uniform_disk_concentric({0.5f, 0.5f}), Vec2(0.0f, 0.0f));
    for (const Vec2 u : {Vec2(0.0f, 0.3f), Vec2(0.8f, 0.0f), Vec2(0.0f, 0.0f)}) {
        const Vec2 d = sample_uniform_disk_concentric(u);
        EXPECT_NEAR(d.x * d.x + d.y * d.y, 1.0f, 1e-6f);
    }
}

TEST(Warp, DirectionsAreUnitAndOnTheirDomain) {
    for (const Vec2 u : grid_of_u()) {
        const Vec3 cosine = sample_cosine_hemisphere(u);
        const Vec3 hemisphere = sample_uniform_hemisphere(u);
        const Vec3 sphere = sample_uniform_sphere(u);
        const Vec3 cone = sample_uniform_cone(u, 0.5f);
        const Vec3 lobe = sample_phong_lobe(u, 20.0f);
        for (const Vec3& w : {cosine, hemisphere, sphere, cone, lobe}) {
            ASSERT_TRUE(is_finite(w)) << u.x << ", " << u.y;
            EXPECT_NEAR(length(w), 1.0f, 1e-5f) << w;
        }
        EXPECT_GE(cosine.z, 0.0f);
        EXPECT_GE(hemisphere.z, 0.0f);
        EXPECT_GE(cone.z, 0.5f - 1e-6f);
        EXPECT_GT(lobe.z, 0.0f);  // never on the horizon, where the lobe's pdf is 0
    }
}

TEST(Warp, PdfsIntegrateToOne) {
    EXPECT_NEAR(integrate_over_sphere([](const Vec3& w) { return cosine_hemisphere_pdf(w.z); }), 1.0, 1e-5);
    EXPECT_NEAR(integrate_over_sphere([](const Vec3& w) { return w.z >= 0.0f ? uniform_hemisphere_pdf() : 0.0f; }), 1.0,
                1e-5);
    EXPECT_NEAR(integrate_over_sphere([](const Vec3&) { return uniform_sphere_pdf(); }), 1.0, 1e-6);
    for (const float degrees_max : {5.0f, 60.0f, 179.0f}) {
        const float c = std::cos(radians(degrees_max));
        EXPECT_NEAR(integrate_over_sphere([c](const Vec3& w) { return cone_pdf_at(w, c); }), 1.0, 1e-4) << degrees_max;
    }
    for (const float n : {0.0f, 1.0f, 10.0f, 100.0f, 1000.0f}) {
        EXPECT_NEAR(integrate_over_sphere([n](const Vec3& w) { return phong_lobe_pdf(w.z, n); }), 1.0, 1e-4) << n;
    }
    const double disk =
        chi2_detail::integrate_2d([](double x, double y) { return x * x + y * y <= 1.0 ? uniform_disk_pdf() : 0.0f; },
                                  -1.0, 1.0, -1.0, 1.0, 1e-9);
    EXPECT_NEAR(disk, 1.0, 1e-4);
}

TEST(Warp, ConeSamplesStayWithinThetaMax) {
    for (const float degrees_max : {0.1f, 1.0f, 5.0f, 30.0f, 90.0f, 150.0f, 179.0f}) {
        const float cos_max = std::cos(radians(degrees_max));
        // sin θmax of the cone the float cos θmax describes, in double.
        const double one_minus_cos_max = 1.0 - static_cast<double>(cos_max);
        const double sin_max = std::sqrt(one_minus_cos_max * (2.0 - one_minus_cos_max));
        for (const Vec2 u : grid_of_u()) {
            const Vec3 w = sample_uniform_cone(u, cos_max);
            EXPECT_GE(w.z, cos_max) << degrees_max;
            const double sin_theta = std::hypot(static_cast<double>(w.x), static_cast<double>(w.y));
            if (degrees_max > 90.0f) continue;
            EXPECT_LE(sin_theta, sin_max * (1.0 + 1e-6)) << degrees_max;
            // The angle is accurate even where cos θ is within a few float steps of 1: sin θ
            // matches the double-precision value to float precision, where √(1 − cos²θ)
            // would be off by percent for the 0.1° cone.
            const double omc = static_cast<double>(u.x) * one_minus_cos_max;
            const double exact = std::sqrt(omc * (2.0 - omc));
            EXPECT_NEAR(sin_theta, exact, 1e-6 * exact) << degrees_max;
        }
    }
}

TEST(Warp, TriangleBarycentricsAreConvex) {
    for (const Vec2 u : grid_of_u()) {
        const auto [b0, b1, b2] = sample_uniform_triangle(u);
        EXPECT_GE(b0, 0.0f);
        EXPECT_GE(b1, 0.0f);
        EXPECT_GE(b2, 0.0f);
        EXPECT_NEAR(b0 + b1 + b2, 1.0f, 1e-6f);
    }
}

// ---- Chi-square tests of each warp against its pdf --------------------------------------

TEST(SamplingChi2, CosineHemisphere) {
    const Chi2Result r =
        chi2_spherical_grid([](Vec2 u) { return sample_cosine_hemisphere(u); },
                            [](const Vec3& w) { return cosine_hemisphere_pdf(w.z); }, {}, family_options(1'000'000));
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(SamplingChi2, UniformHemisphere) {
    const Chi2Result r = chi2_spherical_grid(
        [](Vec2 u) { return sample_uniform_hemisphere(u); },
        [](const Vec3& w) { return w.z >= 0.0f ? uniform_hemisphere_pdf() : 0.0f; }, {}, family_options(1'000'000));
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(SamplingChi2, UniformSphere) {
    const Chi2Result r =
        chi2_spherical_grid([](Vec2 u) { return sample_uniform_sphere(u); },
                            [](const Vec3&) { return uniform_sphere_pdf(); }, {}, family_options(1'000'000));
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(SamplingChi2, UniformCone) {
    for (const float degrees_max : {5.0f, 30.0f, 90.0f, 150.0f, 179.0f}) {
        const float cos_max = std::cos(radians(degrees_max));
        // A band 25% wider than the cap (in 1 − cos θ) resolves small cones in θ and leaves
        // room outside the cap where a too-wide sampler would be caught.
        const SphericalGrid grid{10, 20, std::max(-1.0, 1.0 - 1.25 * (1.0 - cos_max)), 1.0};
        const Chi2Result r = chi2_spherical_grid([cos_max](Vec2 u) { return sample_uniform_cone(u, cos_max); },
                                                 [cos_max](const Vec3& w) { return cone_pdf_at(w, cos_max); }, grid,
                                                 family_options(500'000));
        EXPECT_TRUE(r.passed) << "theta_max = " << degrees_max << " degrees\n" << r.report;
    }
}

TEST(SamplingChi2, PhongLobe) {
    // Bands in cos θ that hold all but ~1e-4 of each lobe, so the cells resolve its shape.
    const struct {
        float exponent;
        SphericalGrid grid;
    } cases[] = {{1.0f, {10, 20, -1.0, 1.0}}, {10.0f, {10, 20, 0.5, 1.0}}, {100.0f, {20, 20, 0.9, 1.0}}};
    for (const auto& c : cases) {
        const float n = c.exponent;
        const Chi2Result r = chi2_spherical_grid([n](Vec2 u) { return sample_phong_lobe(u, n); },
                                                 [n](const Vec3& w) { return phong_lobe_pdf(w.z, n); }, c.grid,
                                                 family_options(1'000'000));
        EXPECT_TRUE(r.passed) << "exponent " << n << "\n" << r.report;
    }
}

TEST(SamplingChi2, ConcentricDisk) {
    const Chi2Result r =
        chi2_planar_grid([](Vec2 u) { return sample_uniform_disk_concentric(u); },
                         [](Vec2 p) { return p.x * p.x + p.y * p.y <= 1.0f ? uniform_disk_pdf() : 0.0f; },
                         {-1.0f, -1.0f}, {1.0f, 1.0f}, 20, 20, family_options(1'000'000));
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(SamplingChi2, UniformTriangle) {
    // A scalene triangle in [0,1]² whose slanted edges cross the 20×20 cells at arbitrary
    // places; the cells it misses must stay empty (chi2_test fails on any sample there).
    const Vec2 a(0.05f, 0.1f), b(0.95f, 0.3f), c(0.4f, 0.9f);
    const auto edge = [](Vec2 p, Vec2 q, Vec2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    const float area = 0.5f * edge(a, b, c);
    ASSERT_GT(area, 0.1f);
    const Chi2Result r = chi2_planar_grid(
        [&](Vec2 u) {
            const auto [b0, b1, b2] = sample_uniform_triangle(u);
            return b0 * a + b1 * b + b2 * c;
        },
        [&](Vec2 p) {
            const bool inside = edge(a, b, p) >= 0.0f && edge(b, c, p) >= 0.0f && edge(c, a, p) >= 0.0f;
            return inside ? 1.0 / area : 0.0;
        },
        {0.0f, 0.0f}, {1.0f, 1.0f}, 20, 20, family_options(1'000'000));
    EXPECT_TRUE(r.passed) << r.report;
}

// ---- DiscreteDistribution ----------------------------------------------------------------

TEST(DiscreteDistribution, Chi2MatchesWeightsAndSkipsZeros) {
    const std::vector<float> weights{0.0f, 1.0f, 3.0f, 0.0f, 0.5f, 2.0f, 0.0f, 7.0f, 0.25f, 0.0f};
    const DiscreteDistribution d(weights);
    constexpr std::size_t kSamples = 1'000'000;
    std::vector<double> observed(weights.size(), 0.0), expected(weights.size(), 0.0);
    pcg32 rng(7);
    for (std::size_t s = 0; s < kSamples; ++s) observed[d.sample(chi2_detail::uniform_float(rng))] += 1.0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        expected[i] = d.pmf(i) * static_cast<double>(kSamples);
        if (weights[i] == 0.0f) {
            EXPECT_EQ(observed[i], 0.0) << "zero-weight entry " << i << " was chosen";
        }
    }
    const Chi2Result r = chi2_test(observed, expected, kSamples, 0.01, kChi2Tests);
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(DiscreteDistribution, RemappedUIsUniformWithinEachEntry) {
    const DiscreteDistribution d({0.0f, 2.0f, 0.5f, 0.0f, 1.5f});
    constexpr int kBins = 10;
    constexpr std::size_t kSamples = 500'000;
    std::vector<double> observed(d.size() * kBins, 0.0), expected(observed.size(), 0.0);
    pcg32 rng(11);
    for (std::size_t s = 0; s < kSamples; ++s) {
        float pmf = -1.0f, u = -1.0f;
        const std::size_t i = d.sample(chi2_detail::uniform_float(rng), &pmf, &u);
        ASSERT_EQ(pmf, d.pmf(i));
        ASSERT_TRUE(u >= 0.0f && u < 1.0f) << u;
        observed[i * kBins + std::min(static_cast<int>(u * kBins), kBins - 1)] += 1.0;
    }
    for (std::size_t i = 0; i < d.size(); ++i) {
        for (int k = 0; k < kBins; ++k) expected[i * kBins + k] = d.pmf(i) * kSamples / kBins;
    }
    const Chi2Result r = chi2_test(observed, expected, kSamples, 0.01, kChi2Tests);
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(DiscreteDistribution, NeverPicksZeroWeightAtCdfEdges) {
    // Total 4: CDF edges at exactly 0, 0.25, 0.25, 0.25, 0.75, 1, 1.
    const std::vector<float> weights{0.0f, 1.0f, 0.0f, 0.0f, 2.0f, 1.0f, 0.0f};
    const DiscreteDistribution d(weights);
    float u_remapped = -1.0f;
    EXPECT_EQ(d.sample(0.0f, nullptr, &u_remapped), 1u);
    EXPECT_EQ(u_remapped, 0.0f);
    EXPECT_EQ(d.sample(std::nextafter(0.25f, 0.0f), nullptr, &u_remapped), 1u);
    EXPECT_LT(u_remapped, 1.0f);
    EXPECT_EQ(d.sample(0.25f, nullptr, &u_remapped), 4u);
    EXPECT_EQ(u_remapped, 0.0f);
    EXPECT_EQ(d.sample(0.75f), 5u);
    EXPECT_EQ(d.sample(std::nextafter(0.75f, 0.0f)), 4u);
    EXPECT_EQ(d.sample(kOneMinusEpsilon, nullptr, &u_remapped), 5u);
    EXPECT_LT(u_remapped, 1.0f);
    // Outside the contract, still a valid entry.
    EXPECT_EQ(d.sample(1.0f), 5u);
    EXPECT_EQ(d.sample(-0.5f), 1u);
    EXPECT_EQ(d.sample(std::numeric_limits<float>::quiet_NaN()), 1u);
    // Every float within 256 steps of each edge.
    for (const float edge : {0.0f, 0.25f, 0.75f, 1.0f}) {
        float lo = edge, hi = edge;
        for (int k = 0; k < 256; ++k) {
            lo = std::nextafter(lo, -1.0f);
            hi = std::nextafter(hi, 2.0f);
            for (const float u : {lo, hi}) EXPECT_GT(weights[d.sample(u)], 0.0f) << "u = " << u;
        }
    }
}

TEST(DiscreteDistribution, PmfAndTotal) {
    const DiscreteDistribution d({0.5f, 0.0f, 1.5f, 2.0f});
    EXPECT_EQ(d.size(), 4u);
    EXPECT_FLOAT_EQ(d.total(), 4.0f);
    EXPECT_FLOAT_EQ(d.pmf(0), 0.125f);
    EXPECT_EQ(d.pmf(1), 0.0f);
    EXPECT_FLOAT_EQ(d.pmf(2) + d.pmf(3), 0.875f);
    const DiscreteDistribution one({3.0f});
    float pmf = 0.0f, u = 0.0f;
    EXPECT_EQ(one.sample(0.3f, &pmf, &u), 0u);
    EXPECT_EQ(pmf, 1.0f);
    EXPECT_FLOAT_EQ(u, 0.3f);
}

TEST(DiscreteDistribution, RejectsBadWeights) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const std::vector<float>& weights :
         std::vector<std::vector<float>>{{}, {1.0f, -0.5f}, {1.0f, nan}, {inf, 1.0f}, {0.0f, 0.0f, 0.0f}, {-0.0f}}) {
        EXPECT_THROW(DiscreteDistribution{weights}, std::invalid_argument) << weights.size() << " weights";
    }
}
