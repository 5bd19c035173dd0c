// srgb_byte (the PNG path's table of levels) against what it replaces, display_byte of
// linear_to_srgb: the same level for every float near each of the 255 steps, for a
// million others across and beyond [0, 1], and for the values that are not numbers.
// (Every float in [0, 1.5) was checked once outside the suite: none differs.)
#include "glint/image/srgb_byte.h"
#include "glint/math/color.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

using namespace glint;

namespace {

uint8_t reference(float linear) { return display_byte(linear_to_srgb(linear)); }

}  // namespace

TEST(SrgbByte, StepsWhereTheCurveSteps) {
    // Walk up from 0 in ulps around each step: every float within 64 ulps of a change.
    const uint32_t one = std::bit_cast<uint32_t>(1.0f);
    int steps = 0;
    for (uint32_t lo = 0; reference(std::bit_cast<float>(lo)) < reference(1.0f);) {
        // The first float above `lo` at a higher level: doubling the distance, then bisecting.
        const uint8_t level = reference(std::bit_cast<float>(lo));
        uint32_t hi = lo + 1;
        while (reference(std::bit_cast<float>(hi)) == level) hi = std::min(one, lo + 2 * (hi - lo));
        while (hi - lo > 1) {
            const uint32_t middle = lo + (hi - lo) / 2;
            (reference(std::bit_cast<float>(middle)) == level ? lo : hi) = middle;
        }
        for (uint32_t u = hi > 64 ? hi - 64 : 0; u <= std::min(one, hi + 64); ++u)
            ASSERT_EQ(srgb_byte(std::bit_cast<float>(u)), reference(std::bit_cast<float>(u)))
                << "at " << std::bit_cast<float>(u) << ", near the step up to level "
                << int(reference(std::bit_cast<float>(hi)));
        ++steps;
        lo = hi;
    }
    EXPECT_EQ(steps, 255);
}

TEST(SrgbByte, AgreesEverywhereElse) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> values(-0.25f, 1.5f);
    for (int i = 0; i < 1'000'000; ++i) {
        const float x = values(rng);
        ASSERT_EQ(srgb_byte(x), reference(x)) << "at " << x;
    }
    for (const float x :
         {0.0f, -0.0f, std::numeric_limits<float>::denorm_min(), 1.0f, 1e30f, std::numeric_limits<float>::infinity(),
          -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()})
        EXPECT_EQ(srgb_byte(x), reference(x)) << "at " << x;
    EXPECT_EQ(srgb_byte(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(srgb_byte(2.0f), 255);
}
