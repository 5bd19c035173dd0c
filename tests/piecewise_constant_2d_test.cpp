// PiecewiseConstant2D against its density: a chi-square test on a grid finer than its cells,
// the density's integral, and zero-weight cells never sampled.

#include "glint/sampling/piecewise_constant_2d.h"
#include "chi2.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using namespace glint;

namespace {

// 4 × 3 cells of very different weights, a zero cell and a zero row among them.
const std::vector<float> kWeights{1.0f, 2.0f, 0.0f, 5.0f,  //
                                  0.0f, 0.0f, 0.0f, 0.0f,  //
                                  0.5f, 8.0f, 3.0f, 0.25f};

TEST(PiecewiseConstant2D, Chi2MatchesWeights) {
    const PiecewiseConstant2D d(kWeights, 4, 3);
    const Chi2Result r = chi2_planar(
        [&](Vec2 u) -> std::optional<Vec2> {
            float pdf = 0.0f;
            const Vec2 p = d.sample(u, &pdf);
            return pdf == d.pdf(p) ? std::optional<Vec2>(p) : std::nullopt;
        },
        [&](Vec2 p) { return double(d.pdf(p)); }, Vec2(0.0f, 0.0f), Vec2(1.0f, 1.0f), 16, 12);
    EXPECT_TRUE(r.passed) << r.report;
}

TEST(PiecewiseConstant2D, DensityIntegratesToOneAndMatchesTheWeights) {
    const PiecewiseConstant2D d(kWeights, 4, 3);
    float total = 0.0f;
    for (float w : kWeights) total += w;
    double integral = 0.0;
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 4; ++x) {
            const float pdf = d.pdf(Vec2((float(x) + 0.5f) / 4.0f, (float(y) + 0.5f) / 3.0f));
            EXPECT_FLOAT_EQ(pdf, kWeights[std::size_t(y * 4 + x)] / total * 12.0f) << x << ", " << y;
            integral += double(pdf) / 12.0;
        }
    }
    EXPECT_NEAR(integral, 1.0, 1e-6);
}

TEST(PiecewiseConstant2D, RejectsAWrongCountAndAllZero) {
    EXPECT_THROW(PiecewiseConstant2D(kWeights, 4, 4), std::invalid_argument);
    EXPECT_THROW(PiecewiseConstant2D(std::vector<float>(6, 0.0f), 3, 2), std::invalid_argument);
}

}  // namespace
