// End-to-end: every scene in scenes/ renders at 64×48 and matches its committed reference
// image, tests/references/<scene>.exr (linear float).
//
// The renderer is deterministic (each pixel draws from its own random stream), so a
// difference can only come from the compiler or the CPU (FMA contraction, -march=native,
// libm); those move values by a few ulps but can flip a sample that grazes an edge or a
// shadow boundary, changing its pixel a lot. Hence two limits: at most 0.5% of the pixels
// (15) may be off by more than 0.01, and the others must agree to a mean error of 5e-5,
// fifty times the drift rounding causes. A material whose diffuse colour changes by 0.01
// already fails (ReferenceComparison.DetectsAChangedScene).
//
// References are rewritten only on purpose, after looking at the new images:
//   GLINT_UPDATE_REFERENCES=1 ctest -R Scenes
// (tests/references/README.md).

#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "glint/scene/default_scene.h"
#include "glint/scene/render_scene.h"

#include "example_scenes.h"
#include "source_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

namespace glint {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;

/// Per channel, |a - b| relative to the reference where it is brighter than 1 (HDR skies
/// and highlights), absolute below. Pixels with a channel off by more than kOutlierError
/// are outliers (a sample that flipped across an edge); the rest must agree to within
/// rounding.
struct ImageDifference {
    /// Fraction of pixels that are outliers.
    double outlier_fraction = 0.0;
    /// Mean error per channel over the other pixels.
    double inlier_mean_error = 0.0;
};
constexpr double kOutlierError = 0.01;
constexpr double kMaxOutlierFraction = 0.005;  // 15 of 64×48 pixels
constexpr double kMaxInlierMeanError = 5e-5;   // ulp-level drift is about 1e-6

ImageDifference compare(const Image& image, const Image& reference) {
    const std::size_t pixels = std::size_t(image.width) * image.height;
    std::size_t outliers = 0;
    double inlier_sum = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        double worst = 0.0, sum = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double a = image.pixels[p * image.channels + c], b = reference.pixels[p * reference.channels + c];
            const double e = std::abs(a - b) / std::max(1.0, std::abs(b));
            sum += e;
            worst = std::max(worst, e);
        }
        if (worst > kOutlierError) {
            ++outliers;
        } else {
            inlier_sum += sum;
        }
    }
    ImageDifference d;
    d.outlier_fraction = double(outliers) / double(pixels);
    d.inlier_mean_error = outliers == pixels ? 0.0 : inlier_sum / double((pixels - outliers) * 3);
    return d;
}

bool matches(const ImageDifference& d) {
    return d.outlier_fraction <= kMaxOutlierFraction && d.inlier_mean_error < kMaxInlierMeanError;
}

std::ostream& operator<<(std::ostream& os, const ImageDifference& d) {
    return os << 100.0 * d.outlier_fraction << "% of pixels off by more than " << kOutlierError << " (limit "
              << 100.0 * kMaxOutlierFraction << "%), mean error of the others " << d.inlier_mean_error << " (limit "
              << kMaxInlierMeanError << ")";
}

Image render(LoadedScene& loaded) {
    loaded.settings.width = kWidth;
    loaded.settings.height = kHeight;
    const RenderScene prepared(std::move(loaded.scene));
    Film film(kWidth, kHeight);
    make_integrator(loaded.settings)->render(prepared, loaded.settings, film);
    return film.to_image();
}

bool updating_references() {
    const char* v = std::getenv("GLINT_UPDATE_REFERENCES");
    return v && std::string(v) == "1";
}

class SceneReference : public testing::TestWithParam<std::string> {};

TEST_P(SceneReference, MatchesReference) {
    const std::string name = GetParam();
    LoadedScene loaded = load_toml_scene(glint_test::kScenesDir / (name + ".toml"));
    const Image image = render(loaded);
    const std::filesystem::path reference_path = glint_test::kSourceDir / "tests" / "references" / (name + ".exr");
    if (updating_references()) {
        write_image(reference_path, image);
        GTEST_SKIP() << "GLINT_UPDATE_REFERENCES=1: wrote " << reference_path;
    }
    ASSERT_TRUE(std::filesystem::exists(reference_path))
        << reference_path << " is missing: render the scene, look at it, then run "
        << "GLINT_UPDATE_REFERENCES=1 ctest -R Scenes and commit the new reference";
    const Image reference = read_image(reference_path);
    ASSERT_EQ(reference.width, image.width);
    ASSERT_EQ(reference.height, image.height);
    ASSERT_GE(reference.channels, 3);
    const ImageDifference d = compare(image, reference);
    EXPECT_TRUE(matches(d)) << name << ": " << d;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneReference,
                         testing::ValuesIn(glint_test::example_scene_names(glint_test::kSourceDir)),
                         [](const testing::TestParamInfo<std::string>& p) { return p.param; });

TEST(ReferenceComparison, DetectsAChangedScene) {
    // The check must be able to fail: the spheres scene without its mirror reflections
    // (max depth 0), or with its red material 0.01 redder, must not pass as the reference.
    const Image reference = read_image(glint_test::kSourceDir / "tests" / "references" / "spheres.exr");
    LoadedScene flat = load_toml_scene(glint_test::kScenesDir / "spheres.toml");
    flat.settings.max_depth = 0;
    const ImageDifference flat_difference = compare(render(flat), reference);
    EXPECT_FALSE(matches(flat_difference)) << flat_difference;

    std::ifstream in(glint_test::kScenesDir / "spheres.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string red = "diffuse = [0.63, 0.105, 0.07]";
    ASSERT_NE(text.find(red), std::string::npos);
    text.replace(text.find(red), red.size(), "diffuse = [0.64, 0.105, 0.07]");
    LoadedScene redder = load_toml_scene_string(text, "spheres.toml", glint_test::kScenesDir);
    const ImageDifference redder_difference = compare(render(redder), reference);
    EXPECT_FALSE(matches(redder_difference)) << redder_difference;
}

TEST(ReferenceComparison, SpheresFileRendersLikeTheBuiltInScene) {
    LoadedScene file = load_toml_scene(glint_test::kScenesDir / "spheres.toml");
    LoadedScene built_in;
    built_in.scene = make_spheres_scene();
    built_in.settings = file.settings;
    const ImageDifference d = compare(render(file), render(built_in));
    EXPECT_EQ(d.outlier_fraction, 0.0) << d;
    EXPECT_LT(d.inlier_mean_error, 1e-6) << d;
}

}  // namespace
}  // namespace glint
