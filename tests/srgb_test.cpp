// sRGB decoding: 8-bit colour images are decoded to linear, alpha and float images are not.

#include "gltf_test_files.h"
#include "png_file.h"

#include "glint/image/image_io.h"
#include "glint/assets/gltf_scene_loader.h"
#include "glint/math/color.h"

#include "source_paths.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace {

TEST(Srgb, TransferFunctionKnownValues) {
    EXPECT_FLOAT_EQ(glint::srgb_to_linear(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(glint::srgb_to_linear(1.0f), 1.0f);
    EXPECT_NEAR(glint::srgb_to_linear(0.04045f), 0.04045f / 12.92f, 1e-7f);  // end of the linear segment
    EXPECT_NEAR(glint::srgb_to_linear(0.5f), 0.214041f, 1e-5f);
    EXPECT_NEAR(glint::srgb_to_linear(188.0f / 255.0f), 0.5029f, 1e-3f);
    for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(glint::linear_to_srgb(glint::srgb_to_linear(v)), v, 1e-5f);
}

/// Write 8-bit RGBA pixels byte for byte (no Glint encoding, no alpha association).
void write_rgba8(const std::filesystem::path& path, const std::vector<unsigned char>& rgba, int w, int h) {
    glint_test::write_png8(path, w, h, 4, rgba);
}

TEST(Srgb, EightBitPngDecodesColourButNotAlpha) {
    const auto path = glint_test::temp_dir() / "rgba.png";
    write_rgba8(path, {128, 188, 255, 255, 0, 10, 64, 128}, 2, 1);
    const glint::Image color = glint::read_image(path, glint::ColorEncoding::Color);
    ASSERT_EQ(color.channels, 4);
    EXPECT_NEAR(color.at(0, 0, 0), glint::srgb_to_linear(128.0f / 255.0f), 1e-5f);
    EXPECT_NEAR(color.at(0, 0, 1), glint::srgb_to_linear(188.0f / 255.0f), 1e-5f);
    EXPECT_NEAR(color.at(0, 0, 2), 1.0f, 1e-6f);
    EXPECT_NEAR(color.at(1, 0, 3), 128.0f / 255.0f, 1e-5f) << "alpha is coverage, never decoded";
    const glint::Image data = glint::read_image(path, glint::ColorEncoding::Data);
    EXPECT_NEAR(data.at(0, 0, 0), 128.0f / 255.0f, 1e-5f);
}

TEST(Srgb, EveryEightBitLevelDecodesExactlyAsTheFormula) {
    const auto path = glint_test::temp_dir() / "levels.png";
    std::vector<unsigned char> levels(256);
    for (int level = 0; level < 256; ++level) levels[std::size_t(level)] = static_cast<unsigned char>(level);
    glint_test::write_png8(path, 256, 1, 1, levels);
    const glint::Image color = glint::read_image(path, glint::ColorEncoding::Color);
    for (int level = 0; level < 256; ++level)
        EXPECT_EQ(color.at(level, 0, 0), glint::srgb_to_linear(float(level) * (1.0f / 255.0f))) << "level " << level;
}

TEST(Srgb, SixteenBitValuesBetweenEightBitLevelsDecodeByTheFormula) {
    // Values that are not one of the 256 values of 8-bit levels must not be rounded to one.
    const auto path = glint_test::temp_dir() / "wide.png";
    const std::vector<uint16_t> values = {1, 1000, 30000, 40001, 65534, 32896, 257};
    glint_test::write_png16(path, int(values.size()), 1, 1, values);
    const glint::Image color = glint::read_image(path, glint::ColorEncoding::Color);
    for (std::size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(color.at(int(i), 0, 0), glint::srgb_to_linear(float(values[i]) * (1.0f / 65535.0f)))
            << "value " << values[i];
}

TEST(Srgb, GltfTextureIsDecodedWithStraightAlpha) {
    // glTF base colour is sRGB with unassociated alpha: a half-transparent texel keeps its colour.
    const auto dir = glint_test::temp_dir();
    write_rgba8(dir / "tex.png", {188, 188, 188, 128}, 1, 1);
    nlohmann::json j = glint_test::quad_json("quad.bin");
    j["images"] = nlohmann::json::array({{{"uri", "tex.png"}}});
    j["textures"] = nlohmann::json::array({{{"source", 0}}});
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    j["materials"][0]["alphaMode"] = "MASK";
    const glint::GltfScene s = glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", j));
    const glint::Material& m = s.loaded.scene.materials()[0];
    ASSERT_NE(m.texture, nullptr);
    EXPECT_NEAR(m.texture->evaluate({0.5f, 0.5f}, {}).g, glint::srgb_to_linear(188.0f / 255.0f), 1e-5f);
    EXPECT_NEAR(m.texture->alpha({0.5f, 0.5f}), 128.0f / 255.0f, 1e-5f);
    EXPECT_EQ(m.alpha_texture, m.texture) << "MASK cuts out by the base colour alpha";
}

TEST(Srgb, HdrFilesStayLinearAndPalettePngDecodes) {
    const std::filesystem::path data = glint_test::kSharedDataDir;
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
