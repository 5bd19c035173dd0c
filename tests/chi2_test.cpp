// The chi-square harness (tests/chi2.h) against known values, and proof that it fails: a
// goodness-of-fit test that cannot reject a wrong pdf proves nothing.

#include "chi2.h"
#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace glint;

TEST(Chi2, IncompleteGammaMatchesClosedForms) {
    for (const double x : {0.01, 0.5, 1.0, 2.5, 7.0, 30.0, 200.0}) {
        // Q(1, x) = e^-x; Q(1/2, x) = erfc(√x); Q(3, x) = e^-x (1 + x + x²/2). Both the series
        // (x < a + 1) and the continued fraction (x ≥ a + 1) are exercised.
        EXPECT_NEAR(regularized_upper_gamma(1.0, x), std::exp(-x), 1e-13) << x;
        EXPECT_NEAR(regularized_upper_gamma(0.5, x), std::erfc(std::sqrt(x)), 1e-13) << x;
        EXPECT_NEAR(regularized_upper_gamma(3.0, x), std::exp(-x) * (1.0 + x + 0.5 * x * x), 1e-13) << x;
    }
    EXPECT_EQ(regularized_upper_gamma(4.0, 0.0), 1.0);
}

TEST(Chi2, PValuesMatchChiSquareTables) {
    // Upper critical values of the χ² distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
    const struct {
        int dof;
        double statistic, p;
    } table[] = {{1, 3.841, 0.05}, {1, 6.635, 0.01}, {10, 23.209, 0.01}, {10, 15.987, 0.10}, {100, 135.807, 0.01}};
    for (const auto& row : table) {
        EXPECT_NEAR(regularized_upper_gamma(0.5 * row.dof, 0.5 * row.statistic), row.p, 2e-4) << row.dof;
    }
}

TEST(Chi2, AcceptsAFitAndRejectsASkew) {
    const std::vector<double> expected(20, 500.0);
    std::vector<double> observed = expected;
    EXPECT_TRUE(chi2_test(observed, expected, 10'000).passed);
    observed[0] += 150.0;
    observed[1] -= 150.0;
    const Chi2Result r = chi2_test(observed, expected, 10'000);
    EXPECT_FALSE(r.passed);
    EXPECT_LT(r.p_value, 1e-6);
    EXPECT_NE(r.report.find("chi2 = 90"), std::string::npos) << r.report;
    EXPECT_NE(r.report.find("dof = 19"), std::string::npos) << r.report;
}

TEST(Chi2, PoolsCellsExpectingFewerThanFive) {
    // Three cells of 2 pool into one group of 6; with the two cells of 100 that is 3 groups.
    const Chi2Result r = chi2_test({2, 2, 2, 100, 100}, {2, 2, 2, 100, 100}, 206);
    EXPECT_TRUE(r.passed) << r.report;
    EXPECT_NE(r.report.find("dof = 2,"), std::string::npos) << r.report;
    EXPECT_NE(r.report.find("3 cells pooled"), std::string::npos) << r.report;
}

TEST(Chi2, FailsOnSamplesInAnImpossibleCell) {
    const Chi2Result r = chi2_test({1, 499, 500}, {0, 500, 500}, 1000);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.report.find("expected count is ~0"), std::string::npos) << r.report;
}

TEST(Chi2, RemainderCellAccountsForMissingSamples) {
    // 200 of 1000 samples rejected, as the expectation says: a fit.
    EXPECT_TRUE(chi2_test({400, 400}, {400, 400}, 1000).passed);
    // 10 samples lost where the pdf puts none: not a fit, though the cells alone look fine.
    EXPECT_FALSE(chi2_test({495, 495}, {500, 500}, 1000).passed);
}

TEST(Chi2, SidakCorrectionTightensThePerTestLevel) {
    // χ² = 2·44²/500 = 7.74 with 1 dof: p ≈ 0.0054, below 0.01 but above 1 − 0.99^(1/10) ≈ 0.001.
    const std::vector<double> expected{500, 500}, observed{544, 456};
    const Chi2Result single = chi2_test(observed, expected, 1000, 0.01, 1);
    EXPECT_NEAR(single.p_value, 0.0054, 2e-4);
    EXPECT_FALSE(single.passed);
    EXPECT_TRUE(chi2_test(observed, expected, 1000, 0.01, 10).passed);
}

TEST(Chi2Spherical, AcceptsTheRightPdfAndRejectsAMismatchedOne) {
    const auto cosine = [](Vec2 u) { return sample_cosine_hemisphere(u); };
    EXPECT_TRUE(chi2_spherical(
                    cosine, [](const Vec3& w) { return cosine_hemisphere_pdf(w.z); }, 10, 20, 200'000)
                    .passed);
    // Right support, wrong shape.
    const Chi2Result uniform = chi2_spherical(
        cosine, [](const Vec3& w) { return w.z >= 0.0f ? uniform_hemisphere_pdf() : 0.0f; }, 10, 20, 200'000);
    EXPECT_FALSE(uniform.passed) << uniform.report;
    // A subtle mismatch: cos^1.1 θ instead of cos θ.
    const Chi2Result subtle = chi2_spherical(
        cosine, [](const Vec3& w) { return phong_lobe_pdf(w.z, 1.1f); }, 10, 20, 1'000'000);
    EXPECT_FALSE(subtle.passed) << subtle.report;
    // Samples where the pdf says none can go.
    const Chi2Result support =
        chi2_spherical([](Vec2 u) { return sample_uniform_sphere(u); },
                       [](const Vec3& w) { return w.z >= 0.0f ? 2.0 * uniform_sphere_pdf() : 0.0; }, 10, 20, 200'000);
    EXPECT_FALSE(support.passed) << support.report;
}

TEST(Chi2Spherical, RejectedSamplesLowerTheExpectedCounts) {
    // Rejects u.x < 1/4 and otherwise samples the sphere uniformly: density (3/4)/(4π).
    const auto sample = [](Vec2 u) -> std::optional<Vec3> {
        if (u.x < 0.25f) return std::nullopt;
        return sample_uniform_sphere({(u.x - 0.25f) / 0.75f, u.y});
    };
    const Chi2Result right = chi2_spherical(sample, [](const Vec3&) { return 0.75 * uniform_sphere_pdf(); });
    EXPECT_TRUE(right.passed) << right.report;
    const Chi2Result wrong = chi2_spherical(sample, [](const Vec3&) { return uniform_sphere_pdf(); });
    EXPECT_FALSE(wrong.passed) << wrong.report;
}

TEST(Chi2Spherical, NonUnitDirectionsFail) {
    const Chi2Result r = chi2_spherical([](Vec2 u) { return 1.01f * sample_uniform_sphere(u); },
                                        [](const Vec3&) { return uniform_sphere_pdf(); }, 10, 20, 100'000);
    EXPECT_FALSE(r.passed) << r.report;
}

TEST(Chi2Planar, AcceptsTheRightDensityAndRejectsAWrongOne) {
    const auto square = [](Vec2 u) { return u; };
    EXPECT_TRUE(chi2_planar(
                    square, [](Vec2) { return 1.0; }, {0, 0}, {1, 1}, 20, 20, 200'000)
                    .passed);
    // A ramp of the same total mass.
    const Chi2Result ramp = chi2_planar(
        square, [](Vec2 p) { return 0.9 + 0.2 * p.x; }, {0, 0}, {1, 1}, 20, 20, 1'000'000);
    EXPECT_FALSE(ramp.passed) << ramp.report;
    // Points off the rectangle land in the remainder cell, where the pdf expects none.
    const Chi2Result off =
        chi2_planar([](Vec2 u) { return 1.01f * u; }, [](Vec2) { return 1.0; }, {0, 0}, {1, 1}, 20, 20, 200'000);
    EXPECT_FALSE(off.passed) << off.report;
}
