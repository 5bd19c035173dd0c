// Display transforms: the tone curves against values computed from their published
// formulas (an independent Python transcription of each source, digits below), automatic
// exposure against the light-meter definition, and where write_image applies them.
#include "glint/image/display_transform.h"
#include "glint/image/image_io.h"
#include "glint/scene_file.h"
#include "glint/scene_format/toml_scene_loader.h"

#include "source_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace glint;
namespace fs = std::filesystem;

namespace {

struct Reference {
    Color in, out;
};

void expect_curve(ToneCurve curve, std::initializer_list<Reference> references) {
    for (const Reference& r : references) {
        const Color got = apply_tone_curve(curve, r.in);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], r.out[c], 2e-4f) << tone_curve_name(curve) << " of " << r.in << " channel " << c;
    }
}

fs::path test_dir() {
    fs::path dir = fs::temp_directory_path() /
                   ("glint_display_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

Image uniform(int width, int height, float value) {
    Image image(width, height, 3);
    for (float& v : image.pixels) v = value;
    return image;
}

}  // namespace

// Khronos PBR Neutral (KhronosGroup/ToneMapping PBR_Neutral/README.md).
TEST(ToneCurve, PbrNeutralMatchesTheKhronosReference) {
    expect_curve(ToneCurve::PbrNeutral, {{Color(0.18f), Color(0.14f)},
                                         {Color(1.0f), Color(0.869091f)},
                                         {Color(4.0f), Color(0.983256f)},
                                         {{0.02f, 0.3f, 0.9f}, {0.007559f, 0.272777f, 0.841103f}},
                                         {{3.0f, 0.5f, 0.1f}, {0.976393f, 0.340840f, 0.239151f}}});
}

TEST(ToneCurve, PbrNeutralLeavesBaseColoursBelowTheCompressionStartAlone) {
    // Above the toe (min channel >= 0.08) and under 0.76 only the 0.04 offset applies: a
    // base colour lit by white light of 1 shows as itself, the curve's design goal.
    const Color base(0.7f, 0.35f, 0.1f);
    const Color got = apply_tone_curve(ToneCurve::PbrNeutral, base);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], base[c] - 0.04f, 1e-6f);
}

// Stephen Hill's ACES fit (BakingLab ACES.hlsl) with three.js' 1/0.6 exposure boost.
TEST(ToneCurve, AcesMatchesHillsFit) {
    expect_curve(ToneCurve::Aces, {{Color(0.18f), Color(0.213105f)},
                                   {Color(1.0f), Color(0.763397f)},
                                   {Color(4.0f), Color(0.952237f)},
                                   {{0.02f, 0.3f, 0.9f}, {0.054990f, 0.375841f, 0.730932f}},
                                   {{3.0f, 0.5f, 0.1f}, {1.0f, 0.639517f, 0.264255f}}});
}

// Minimal AgX (Wrensch 2023, from Sobotka's configuration): middle grey lands at display
// value 0.5 (0.2145 linear under the 2.2 display gamma).
TEST(ToneCurve, AgxMatchesTheMinimalImplementation) {
    expect_curve(ToneCurve::Agx, {{Color(0.18f), {0.214467f, 0.214533f, 0.214537f}},
                                  {Color(1.0f), {0.589977f, 0.590207f, 0.590221f}},
                                  {Color(4.0f), {0.860622f, 0.861003f, 0.861027f}},
                                  {{0.02f, 0.3f, 0.9f}, {0.104766f, 0.330365f, 0.594634f}},
                                  {{3.0f, 0.5f, 0.1f}, {0.897222f, 0.462864f, 0.244440f}}});
    EXPECT_NEAR(std::pow(apply_tone_curve(ToneCurve::Agx, Color(0.18f)).g, 1.0f / 2.2f), 0.5f, 0.01f);
}

TEST(ToneCurve, ClampKeepsTheHueOfOverexposedColours) {
    expect_curve(ToneCurve::Clamp, {{{4.0f, 2.0f, 1.0f}, {1.0f, 0.5f, 0.25f}},
                                    {{0.5f, 0.25f, 0.0f}, {0.5f, 0.25f, 0.0f}},
                                    {{-1.0f, 2.0f, 0.5f}, {0.0f, 1.0f, 0.25f}}});
}

TEST(ToneCurve, NoneLeavesValuesForTheEncoderToClip) {
    expect_curve(ToneCurve::None, {{{4.0f, 2.0f, 0.1f}, {4.0f, 2.0f, 0.1f}}});
}

TEST(ToneCurve, EveryCurveButNoneIsMonotonicAndEndsInTheDisplayRange) {
    for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Aces, ToneCurve::Agx, ToneCurve::PbrNeutral}) {
        float previous = -1.0f;
        for (float stops = -12.0f; stops <= 12.0f; stops += 0.25f) {
            const float out = apply_tone_curve(curve, Color(std::exp2(stops))).g;
            EXPECT_GE(out, previous) << tone_curve_name(curve) << " at " << stops << " stops";
            EXPECT_GE(out, 0.0f);
            EXPECT_LE(out, 1.0f);
            previous = out;
        }
        EXPECT_GT(apply_tone_curve(curve, Color(1e6f)).g, 0.95f) << tone_curve_name(curve);
    }
}

TEST(ToneCurve, NamesRoundTrip) {
    for (ToneCurve curve : {ToneCurve::None, ToneCurve::Clamp, ToneCurve::Aces, ToneCurve::Agx, ToneCurve::PbrNeutral})
        EXPECT_EQ(parse_tone_curve(tone_curve_name(curve)), curve);
    EXPECT_FALSE(parse_tone_curve("filmic"));
}

TEST(AutoExposure, AUniformImageBecomesMiddleGrey) {
    for (float radiance : {0.004f, 1.0f, 76.0f}) {
        const float stops = auto_exposure_stops(uniform(4, 3, radiance));
        EXPECT_NEAR(radiance * std::exp2(stops), kMiddleGrey, 1e-5f) << radiance;
    }
}

TEST(AutoExposure, ExposesTheLogAverageOfTheLitPixels) {
    // Two lit pixels of 0.02 and 2 (log-average 0.2) beside black: black is no evidence.
    Image image = uniform(2, 2, 0.0f);
    for (int c = 0; c < 3; ++c) {
        image.at(0, 0, c) = 0.02f;
        image.at(1, 1, c) = 2.0f;
    }
    EXPECT_NEAR(auto_exposure_stops(image), std::log2(0.18f / 0.2f), 1e-5f);
    EXPECT_EQ(auto_exposure_stops(uniform(2, 2, 0.0f)), 0.0f);
}

TEST(Exposure, ParsesStopsAndAuto) {
    EXPECT_EQ(parse_exposure("auto"), (Exposure{true, 0.0f}));
    EXPECT_EQ(parse_exposure("-1.5"), (Exposure{false, -1.5f}));
    for (const char* bad : {"", "bright", "1.5x", "nan", "inf"}) EXPECT_FALSE(parse_exposure(bad)) << bad;
}

TEST(DisplayTransform, AppliesToDisplayFormatsOnly) {
    const fs::path dir = test_dir();
    const Image bright = uniform(1, 1, 4.0f);
    WriteOptions neutral;
    neutral.tone_curve = ToneCurve::PbrNeutral;
    write_image(dir / "neutral.png", bright, neutral);
    write_image(dir / "none.png", bright);
    write_image(dir / "neutral.exr", bright, neutral);
    // PNG: 4.0 compresses to 0.983 (sRGB 0.9926) instead of clipping at 1.
    EXPECT_NEAR(read_image(dir / "neutral.png", ColorEncoding::Data).at(0, 0, 0), linear_to_srgb(0.983256f),
                0.6f / 255.0f);
    EXPECT_EQ(read_image(dir / "none.png", ColorEncoding::Data).at(0, 0, 0), 1.0f);
    // EXR keeps radiance.
    EXPECT_EQ(read_image(dir / "neutral.exr").at(0, 0, 0), 4.0f);
    EXPECT_TRUE(keeps_radiance("x.EXR"));
    EXPECT_FALSE(keeps_radiance("x.png"));
    fs::remove_all(dir);
}

TEST(DisplayTransform, ATomlSceneChoosesItsOwn) {
    const LoadedScene loaded = load_toml_scene_string(
        "[display]\ntonemap = \"agx\"\nexposure = \"auto\"\n[[materials]]\nname = \"m\"\n"
        "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"m\"\n",
        "display.toml", ".");
    EXPECT_EQ(loaded.display, (DisplayTransform{ToneCurve::Agx, Exposure{true, 0.0f}}));
    const LoadedScene plain = load_toml_scene_string(
        "[display]\nexposure = -2\n[[materials]]\nname = \"m\"\n[[objects]]\ntype = \"sphere\"\nradius = 1\n"
        "material = \"m\"\n",
        "plain.toml", ".");
    // A TOML scene keeps Glint's classic look unless it asks: no curve.
    EXPECT_EQ(plain.display, (DisplayTransform{ToneCurve::None, Exposure{false, -2.0f}}));
}

TEST(DisplayTransform, GltfScenesAreToneMappedWithPbrNeutral) {
    const fs::path file = glint_test::kTestDataDir / "animated_quads.gltf";
    const SceneFile scene = load_scene_file(file);
    EXPECT_EQ(scene.loaded.display, (DisplayTransform{ToneCurve::PbrNeutral, Exposure{}}));
}
