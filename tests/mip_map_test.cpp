// The MIP pyramid and the filtered checkerboard against closed forms: every level keeps the
// image's mean, a footprint covering the texture returns that mean, and the box-filtered
// checkerboard equals a dense numerical average of the point-sampled one.

#include "glint/image/mip_map.h"
#include "glint/materials/texture.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

using namespace glint;

namespace {

/// A w×h RGB image of pseudo-random values in [0, 1) (a fixed LCG: the same image each run).
std::shared_ptr<const Image> noise_image(int w, int h) {
    auto image = std::make_shared<Image>(w, h, 3);
    uint32_t state = 12345u;
    for (float& v : image->pixels) {
        state = state * 1664525u + 1013904223u;
        v = float(state >> 8) / float(1u << 24);
    }
    return image;
}

double mean_of(const Image& image, int channel) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += image.at(x, y, channel);
    return sum / (double(image.width) * image.height);
}

}  // namespace

TEST(MipMap, HalvesEachAxisDownToOneTexel) {
    const MipMap mip(noise_image(13, 6));
    ASSERT_EQ(mip.levels(), 4u);  // 13×6 → 6×3 → 3×1 → 1×1
    EXPECT_EQ(mip.level(1).width, 6);
    EXPECT_EQ(mip.level(1).height, 3);
    EXPECT_EQ(mip.level(2).width, 3);
    EXPECT_EQ(mip.level(2).height, 1);
    EXPECT_EQ(mip.level(mip.levels() - 1).width, 1);
    EXPECT_EQ(mip.level(mip.levels() - 1).height, 1);
}

TEST(MipMap, EveryLevelKeepsTheMeanForOddSizesToo) {
    // Odd sizes make output texels straddle input texels: only exact fractional weights keep
    // the mean (dropping the partial texels or weighting them whole moves it).
    const auto image = noise_image(13, 7);
    const MipMap mip(image);
    for (std::size_t i = 1; i < mip.levels(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean_of(mip.level(i), c), mean_of(*image, c), 1e-5) << "level " << i;
}

TEST(MipMap, EveryLevelIsTheSameOnOneThreadAsOnMany) {
    // Rows of each level are shared out among tasks (1001×767, so that their rows end at odd
    // places); each value must come from the source alone, whichever thread computes it. A
    // fault there (a buffer shared by the tasks) shows only when tasks overlap in time, so
    // the 8-thread build runs 24 times in an arena of 8: beside two busy processes on this
    // project's 2-core machines, such a fault passed 4 of 6 runs of the old 4 builds in the
    // default arena, and 1 of 8 runs of this.
    const std::shared_ptr<const Image> image = noise_image(1001, 767);
    const MipMap one = tbb::task_arena(1).execute([&] { return MipMap(image); });
    const tbb::global_control eight_threads(tbb::global_control::max_allowed_parallelism, 8);
    tbb::task_arena eight(8);
    for (int build = 0; build < 24; ++build) {
        const MipMap many = eight.execute([&] { return MipMap(image); });
        ASSERT_EQ(one.levels(), many.levels());
        for (std::size_t i = 1; i < one.levels(); ++i) {
            SCOPED_TRACE("build " + std::to_string(build) + ", level " + std::to_string(i));
            ASSERT_EQ(one.level(i).pixels.size(), many.level(i).pixels.size());
            for (std::size_t k = 0; k < one.level(i).pixels.size(); ++k)
                ASSERT_EQ(std::bit_cast<uint32_t>(one.level(i).pixels[k]),
                          std::bit_cast<uint32_t>(many.level(i).pixels[k]))
                    << "value " << k;
        }
    }
}

TEST(MipMap, LevelOfDetailIsLog2OfTheTexelsTheFootprintSpans) {
    const MipMap mip(noise_image(64, 32));
    EXPECT_FLOAT_EQ(mip.level_of_detail(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(mip.level_of_detail(1.0f / 64.0f), 0.0f);  // one texel of the longer side
    EXPECT_FLOAT_EQ(mip.level_of_detail(4.0f / 64.0f), 2.0f);
    EXPECT_FLOAT_EQ(mip.level_of_detail(1.0f / 128.0f), 0.0f);  // magnified: the image itself
    EXPECT_FLOAT_EQ(mip.level_of_detail(1e9f), float(mip.levels() - 1));
    EXPECT_FLOAT_EQ(mip.level_of_detail(std::numeric_limits<float>::infinity()), float(mip.levels() - 1));
}

TEST(MipMap, AFootprintAsWideAsTheTextureGivesItsMean) {
    const auto image = noise_image(16, 16);
    const MipMap mip(image);
    const Color c = mip.sample_color(Vec2(0.3f, 0.7f), 1.0f, WrapMode::Repeat);
    EXPECT_NEAR(c.r, mean_of(*image, 0), 1e-5);
    EXPECT_NEAR(c.g, mean_of(*image, 1), 1e-5);
    EXPECT_NEAR(c.b, mean_of(*image, 2), 1e-5);
}

TEST(MipMap, APointLookupIsBilinearInTheImage) {
    const auto image = noise_image(16, 8);
    const MipMap mip(image);
    const Vec2 uv(0.37f, 0.61f);
    const Color bilinear = sample_bilinear_color(*image, uv, WrapMode::Repeat, WrapMode::Repeat);
    const Color point = mip.sample_color(uv, 0.0f, WrapMode::Repeat);
    EXPECT_EQ(point.r, bilinear.r);
    EXPECT_EQ(point.g, bilinear.g);
    EXPECT_EQ(point.b, bilinear.b);
}

TEST(MipMap, BlendsLinearlyBetweenTheTwoLevelsAroundTheLevelOfDetail) {
    const MipMap mip(noise_image(32, 32));
    const Vec2 uv(0.4f, 0.55f);
    const float width = std::exp2(1.25f) / 32.0f;  // level of detail 1.25
    const Color l1 = sample_bilinear_color(mip.level(1), uv, WrapMode::Repeat, WrapMode::Repeat);
    const Color l2 = sample_bilinear_color(mip.level(2), uv, WrapMode::Repeat, WrapMode::Repeat);
    const Color c = mip.sample_color(uv, width, WrapMode::Repeat);
    EXPECT_NEAR(c.r, 0.75f * l1.r + 0.25f * l2.r, 1e-5f);
    EXPECT_NEAR(c.g, 0.75f * l1.g + 0.25f * l2.g, 1e-5f);
}

TEST(FilteredChecker, AFootprintOfWholePeriodsIsTheMeanColour) {
    const CheckerTexture checks(Color(1.0f), Color(0.0f), 4.0f);
    for (float u : {0.0f, 0.13f, 0.5f, 0.91f, -3.3f})
        for (float v : {0.0f, 0.27f, 0.8f})
            EXPECT_NEAR(checks.evaluate(TextureQuery{Vec2(u, v), Vec3(), 0.5f}).r, 0.5f, 1e-5f) << u << ", " << v;
}

TEST(FilteredChecker, EqualsTheAverageOfPointSamplesOverTheBox) {
    // The closed form against a midpoint rule of the unfiltered checkerboard over the same
    // square box (1000² points: error below 1/500 for a box crossing a few edges).
    const CheckerTexture checks(Color(0.9f), Color(0.1f), 3.0f);
    const struct {
        float u, v, width;
    } cases[] = {{0.1f, 0.2f, 0.2f}, {0.52f, 0.33f, 0.45f}, {-0.4f, 1.7f, 0.9f}, {0.34f, 0.34f, 0.05f}};
    for (const auto& c : cases) {
        constexpr int n = 1000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const float u = c.u + c.width * ((float(i) + 0.5f) / n - 0.5f);
                const float v = c.v + c.width * ((float(j) + 0.5f) / n - 0.5f);
                sum += checks.evaluate(Vec2(u, v), Vec3()).r;
            }
        const float numeric = float(sum / (double(n) * n));
        EXPECT_NEAR(checks.evaluate(TextureQuery{Vec2(c.u, c.v), Vec3(), c.width}).r, numeric, 2e-3f)
            << c.u << ", " << c.v << " over " << c.width;
    }
}

TEST(FilteredChecker, AnUnboundedFootprintGivesTheMeanColourNotNaN) {
    // A footprint can overflow (a huge uv_scale times a wide cone): the whole texture is then
    // under it, so its mean, never NaN.
    const CheckerTexture checks(Color(0.9f), Color(0.1f), 3.0f);
    const Color c = checks.evaluate(TextureQuery{Vec2(0.3f, 0.2f), Vec3(), std::numeric_limits<float>::infinity()});
    EXPECT_FLOAT_EQ(c.r, 0.5f);
}

TEST(FilteredChecker, APointLookupIsTheSquareItFallsIn) {
    const CheckerTexture checks(Color(0.9f), Color(0.1f), 2.0f);
    EXPECT_EQ(checks.evaluate(Vec2(0.1f, 0.1f), Vec3()).r, 0.9f);   // square (0, 0)
    EXPECT_EQ(checks.evaluate(Vec2(0.6f, 0.1f), Vec3()).r, 0.1f);   // (1, 0)
    EXPECT_EQ(checks.evaluate(Vec2(-0.1f, 0.1f), Vec3()).r, 0.1f);  // (−1, 0)
    EXPECT_EQ(checks.evaluate(Vec2(-0.1f, -0.1f), Vec3()).r, 0.9f); // (−1, −1)
}
