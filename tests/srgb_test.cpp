// sRGB decoding: 8-bit colour images are decoded to linear, alpha and float images are not.

#include "glint/image/image_io.h"
#include "glint/math/color.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

namespace {

TEST(Srgb, TransferFunctionKnownValues) {
    EXPECT_FLOAT_EQ(glint::srgb_to_linear(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(glint::srgb_to_linear(1.0f), 1.0f);
    EXPECT_NEAR(glint::srgb_to_linear(0.04045f), 0.04045f / 12.92f, 1e-7f);  // end of the linear segment
    EXPECT_NEAR(glint::srgb_to_linear(0.5f), 0.214041f, 1e-5f);
    EXPECT_NEAR(glint::srgb_to_linear(188.0f / 255.0f), 0.5029f, 1e-3f);
    for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(glint::linear_to_srgb(glint::srgb_to_linear(v)), v, 1e-5f);
}

/// Write 8-bit RGBA pixels with OIIO directly (no Glint encoding in between).
void write_rgba8(const std::filesystem::path& path, const std::vector<unsigned char>& rgba, int w, int h) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgba.data()));
    out->close();
}

TEST(Srgb, EightBitPngDecodesColourButNotAlpha) {
    const auto path = std::filesystem::temp_directory_path() / "glint_srgb_test.png";
    write_rgba8(path, {128, 188, 255, 128, 0, 10, 64, 255}, 2, 1);
    const glint::Image color = glint::read_image(path, glint::ColorEncoding::Color);
    ASSERT_EQ(color.channels, 4);
    EXPECT_NEAR(color.at(0, 0, 0), glint::srgb_to_linear(128.0f / 255.0f), 1e-5f);
    EXPECT_NEAR(color.at(0, 0, 1), glint::srgb_to_linear(188.0f / 255.0f), 1e-5f);
    EXPECT_NEAR(color.at(0, 0, 2), 1.0f, 1e-6f);
    EXPECT_NEAR(color.at(0, 0, 3), 128.0f / 255.0f, 1e-5f) << "alpha is coverage, never decoded";
    EXPECT_NEAR(color.at(1, 0, 1), glint::srgb_to_linear(10.0f / 255.0f), 1e-6f);
    const glint::Image data = glint::read_image(path, glint::ColorEncoding::Data);
    EXPECT_NEAR(data.at(0, 0, 0), 128.0f / 255.0f, 1e-5f);
    std::filesystem::remove(path);
}

TEST(Srgb, HdrFilesStayLinearAndPalettePngDecodes) {
    const std::filesystem::path data(GLINT_SHARED_DATA_DIR);
    const auto hdr = data / "env/equirect/studio_small_03_1k.hdr";
    const auto palette = data / "textures/kenney_prototype_orange_checker_1024.png";
    if (!std::filesystem::exists(hdr) || !std::filesystem::exists(palette)) GTEST_SKIP() << "no shared data";
    const glint::Image env = glint::read_image(hdr);
    float peak = 0.0f;
    for (float v : env.pixels) peak = std::max(peak, v);
    EXPECT_GT(peak, 100.0f) << "HDR values must not be squeezed through the sRGB curve";
    const glint::Image tex = glint::read_image(palette);
    EXPECT_EQ(tex.width, 1024);
    EXPECT_GE(tex.channels, 3);
    const glint::Color c = tex.rgb(10, 10);
    EXPECT_GT(c.r, c.b) << "orange: more red than blue after decoding";
    EXPECT_LE(c.max_component(), 1.0f);
}

}  // namespace
