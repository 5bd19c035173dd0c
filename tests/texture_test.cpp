#include "glint/materials/texture.h"

#include <gtest/gtest.h>

#include <memory>

using namespace glint;

namespace {

/// 2×2 image: black, white / red, green (rows from the top), RGBA with alpha 0 on the left.
std::shared_ptr<Image> two_by_two() {
    auto img = std::make_shared<Image>(2, 2, 4);
    const float px[4][4] = {{0, 0, 0, 0}, {1, 1, 1, 1}, {1, 0, 0, 0}, {0, 1, 0, 1}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 4; ++c) img->pixels[size_t(i) * 4 + c] = px[i][c];
    return img;
}

}  // namespace

TEST(ImageTexture, TexelCentresReturnTexelValues) {
    const ImageTexture tex(two_by_two());
    EXPECT_EQ(tex.evaluate({0.25f, 0.25f}, {}), Color(0, 0, 0));
    EXPECT_EQ(tex.evaluate({0.75f, 0.25f}, {}), Color(1, 1, 1));
    EXPECT_EQ(tex.evaluate({0.25f, 0.75f}, {}), Color(1, 0, 0));  // v grows downwards
}

TEST(ImageTexture, BilinearBetweenTexelCentres) {
    const ImageTexture tex(two_by_two(), WrapMode::Clamp);
    const Color mid = tex.evaluate({0.5f, 0.25f}, {});  // halfway between black and white
    EXPECT_NEAR(mid.r, 0.5f, 1e-6f);
    const Color centre = tex.evaluate({0.5f, 0.5f}, {});  // average of all four
    EXPECT_NEAR(centre.r, 0.5f, 1e-6f);
    EXPECT_NEAR(centre.g, 0.5f, 1e-6f);
    EXPECT_NEAR(centre.b, 0.25f, 1e-6f);
}

TEST(ImageTexture, RepeatAndClampDifferAtTheBorder) {
    const ImageTexture repeat(two_by_two(), WrapMode::Repeat), clamp(two_by_two(), WrapMode::Clamp);
    // u = 0 sits between the last and first texel when repeating, on the first when clamping.
    EXPECT_NEAR(repeat.evaluate({0.0f, 0.25f}, {}).r, 0.5f, 1e-6f);
    EXPECT_NEAR(clamp.evaluate({0.0f, 0.25f}, {}).r, 0.0f, 1e-6f);
    // Repeat is periodic.
    EXPECT_EQ(repeat.evaluate({1.25f, -0.75f}, {}), repeat.evaluate({0.25f, 0.25f}, {}));
}

TEST(ImageTexture, AlphaComesFromTheLastChannel) {
    const ImageTexture tex(two_by_two(), WrapMode::Clamp);
    EXPECT_FLOAT_EQ(tex.alpha({0.25f, 0.25f}), 0.0f);
    EXPECT_FLOAT_EQ(tex.alpha({0.75f, 0.25f}), 1.0f);
    auto rgb = std::make_shared<Image>(1, 1, 3);
    EXPECT_FLOAT_EQ(ImageTexture(rgb).alpha({0.5f, 0.5f}), 1.0f);
}

TEST(CheckerTexture, AlternatesWithScale) {
    const CheckerTexture checker(Color(1.0f), Color(0.0f), 4.0f);
    EXPECT_EQ(checker.evaluate({0.1f, 0.1f}, {}), Color(1.0f));
    EXPECT_EQ(checker.evaluate({0.3f, 0.1f}, {}), Color(0.0f));
    EXPECT_EQ(checker.evaluate({0.3f, 0.3f}, {}), Color(1.0f));
    EXPECT_EQ(checker.evaluate({-0.1f, 0.1f}, {}), Color(0.0f));  // no mirror seam at 0
}
