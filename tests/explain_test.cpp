// `glint explain`: the ray tree of a pixel, checked against what `glint render` writes and
// against Fresnel's formula; its mistakes on the command line get a reason and exit 1.
#include "cli_runner.h"

#include "glint/image/image_io.h"
#include "glint/math/vec3.h"
#include "source_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <string>

namespace {

namespace fs = std::filesystem;
using glint_test::run_cli;
using nlohmann::json;

const std::string kCli = GLINT_CLI;

json explain_json(const std::string& args, const fs::path& dir) {
    const glint_test::CliResult r = run_cli(kCli, "explain " + args + " --json", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out);
}

float rgb_channel(const json& rgb, int c) { return rgb.at(c).get<float>(); }

/// Every sample's rays add up to its radiance, and the value is the filter-weighted mean of
/// the samples; counts the ray kinds seen.
void expect_consistent(const json& pixel, std::map<std::string, int>& kinds) {
    // In double: with a filter's negative lobes (Mitchell) the mean is a difference of larger
    // sums, and a float sum here would differ from the film's by more than its own rounding.
    double value_sum[3] = {0, 0, 0}, weight_sum = 0;
    for (const json& sample : pixel.at("samples")) {
        const double w = sample.at("filter_weight").get<double>();
        weight_sum += w;
        float sum[3] = {0, 0, 0};
        ASSERT_TRUE(sample.contains("rays"));
        const json& rays = sample.at("rays");
        ASSERT_FALSE(rays.empty());
        EXPECT_EQ(rays[0].at("kind"), "camera");
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const json& ray = rays[i];
            ++kinds[ray.at("kind").get<std::string>()];
            if (i > 0) {
                EXPECT_LT(ray.at("parent").get<int>(), int(i)) << "a parent comes before its children";
            }
            for (int c = 0; c < 3; ++c) sum[c] += rgb_channel(ray.at("contribution"), c);
        }
        for (int c = 0; c < 3; ++c) {
            const float radiance = rgb_channel(sample.at("radiance"), c);
            EXPECT_NEAR(sum[c], radiance, 1e-5f * std::abs(radiance) + 1e-6f)
                << "pixel " << pixel.at("pixel") << " sample " << sample.at("index") << " channel " << c;
            value_sum[c] += w * radiance;
        }
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(value_sum[c] / weight_sum, rgb_channel(pixel.at("value"), c),
                    1e-5 * std::abs(value_sum[c] / weight_sum) + 1e-6);
}

/// For pixels across the image: the explained value is the rendered pixel, bit for bit, and
/// the rays add up. Returns how often each ray kind appeared.
std::map<std::string, int> check_against_render(const fs::path& scene, const std::string& settings) {
    const fs::path dir = glint_test::temp_dir();
    const fs::path exr = dir / "render.exr";
    const glint_test::CliResult r =
        run_cli(kCli, "render " + scene.string() + " " + settings + " -q -o " + exr.string(), dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const glint::Image image = glint::read_image(exr);
    std::map<std::string, int> kinds;
    for (int y = 3; y < image.height; y += 9)
        for (int x = 5; x < image.width; x += 11) {
            const json pixel = explain_json(
                scene.string() + " " + settings + " --pixel " + std::to_string(x) + "," + std::to_string(y), dir);
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(rgb_channel(pixel.at("value"), c), image.at(x, y, c))
                    << "pixel " << x << "," << y << " channel " << c;
            expect_consistent(pixel, kinds);
        }
    fs::remove_all(dir);
    return kinds;
}

}  // namespace

TEST(Explain, WhittedValueIsTheRenderedPixelAndTheRaysAddUp) {
    const auto kinds = check_against_render(glint_test::kScenesDir / "whitted1980.toml",
                                            "--width 64 --height 48 --spp 4 --filter mitchell");
    // The scene's mirror and glass spheres give every kind of Whitted ray.
    EXPECT_GT(kinds.at("camera"), 0);
    EXPECT_GT(kinds.count("reflection") ? kinds.at("reflection") : 0, 0);
    EXPECT_GT(kinds.count("refraction") ? kinds.at("refraction") : 0, 0);
    EXPECT_GT(kinds.count("shadow") ? kinds.at("shadow") : 0, 0);
}

TEST(Explain, WhittedWithAreaLightsValueIsTheRenderedPixel) {
    // Area lights' light samples: the product a shadow ray adds must not be fused into the
    // sum differently when it is recorded (3 of these 30 pixels differed in the last bit).
    const auto kinds = check_against_render(glint_test::kScenesDir / "soft_shadows.toml",
                                            "--width 64 --height 48 --spp 4 --filter box");
    EXPECT_GT(kinds.count("shadow") ? kinds.at("shadow") : 0, 0);
}

TEST(Explain, PathValueIsTheRenderedPixelAndTheRaysAddUp) {
    const auto kinds = check_against_render(glint_test::kScenesDir / "cornell_area.toml",
                                            "--width 40 --height 40 --spp 4 --integrator path --depth 4");
    EXPECT_GT(kinds.count("bounce") ? kinds.at("bounce") : 0, 0);
    EXPECT_GT(kinds.count("shadow") ? kinds.at("shadow") : 0, 0);
}

TEST(Explain, WhittedGlossyValueIsTheRenderedPixelAndTheRaysAddUp) {
    // Rough gold and frosted glass under an area light: glossy samples, MIS-weighted light
    // samples and emission, refracted samples inside the glass.
    // Beside the test's folder, which check_against_render empties.
    const fs::path scene = glint_test::temp_dir().string() + "_glossy.toml";
    glint_test::write_file(scene, R"([render]
glossy_samples = 3
light_samples = 2
[camera]
position = [0, 1.2, 4]
look_at = [0, 0.4, 0]
fov = 40
[background]
color = [0.2, 0.3, 0.4]
[world]
ambient_light = 0.1
[[materials]]
name = "floor"
diffuse = 0.6
[[materials]]
name = "gold"
diffuse = 0
reflectivity = [1.0, 0.78, 0.34]
fresnel_mirror = true
roughness = 0.3
[[materials]]
name = "frosted"
diffuse = 0
transparency = 1
roughness = 0.4
[[lights]]
type = "quad"
corner = [-0.5, 2.5, -0.5]
edge_u = [1, 0, 0]
edge_v = [0, 0, 1]
radiance = 8
[[objects]]
type = "plane"
size = 10
material = "floor"
[[objects]]
type = "sphere"
center = [-0.6, 0.5, 0]
radius = 0.5
material = "gold"
[[objects]]
type = "sphere"
center = [0.6, 0.5, 0.2]
radius = 0.5
material = "frosted"
)");
    const auto kinds = check_against_render(scene, "--width 64 --height 48 --spp 4 --filter tent");
    EXPECT_GT(kinds.count("glossy reflection") ? kinds.at("glossy reflection") : 0, 0);
    EXPECT_GT(kinds.count("glossy transmission") ? kinds.at("glossy transmission") : 0, 0);
    EXPECT_GT(kinds.count("shadow") ? kinds.at("shadow") : 0, 0);
    fs::remove(scene);
}

TEST(Explain, MirrorSphereUnderAPointLightGivesTheFormulasTree) {
    const fs::path dir = glint_test::temp_dir();
    // Half mirror, half Lambert, lit by a point light beside the camera: the camera ray hits
    // at t = |eye − p|, its shadow ray brings kd·I·cos θ / d², and its reflection (factor kr)
    // sees the background.
    glint_test::write_file(dir / "mirror.toml", R"([render]
width = 9
height = 9
max_depth = 1
[camera]
position = [0, 0, 5]
look_at = [0, 0, 0]
fov = 20
[background]
color = [0.2, 0.3, 0.4]
[world]
ambient_light = 0
[[materials]]
name = "half mirror"
diffuse = 0.5
reflectivity = 0.5
[[lights]]
type = "point"
position = [0, 3, 5]
intensity = 10
falloff = "inverse_square"
[[objects]]
name = "ball"
type = "sphere"
center = [0, 0, 0]
radius = 1
material = "half mirror"
)");
    const fs::path exr = dir / "mirror.exr";
    ASSERT_EQ(run_cli(kCli, "render " + (dir / "mirror.toml").string() + " -q -o " + exr.string(), dir).exit_code, 0);
    const glint::Image image = glint::read_image(exr);
    const json e = explain_json((dir / "mirror.toml").string() + " --pixel 4,4", dir);
    const json& rays = e.at("samples").at(0).at("rays");
    ASSERT_EQ(rays.size(), 3u) << rays.dump(1);
    const json &camera = rays[0], &shadow = rays[1], &reflection = rays[2];
    EXPECT_EQ(camera.at("kind"), "camera");
    EXPECT_EQ(shadow.at("kind"), "shadow");
    EXPECT_EQ(reflection.at("kind"), "reflection");
    EXPECT_EQ(shadow.at("parent"), 0);
    EXPECT_EQ(reflection.at("parent"), 0);
    // Where the camera ray meets the sphere, from the ray itself.
    auto vec = [](const json& j) { return glint::Vec3(j[0].get<float>(), j[1].get<float>(), j[2].get<float>()); };
    const glint::Vec3 origin = vec(camera.at("origin")), direction = vec(camera.at("direction"));
    const float b = glint::dot(origin, direction), c = glint::dot(origin, origin) - 1.0f;
    const float t = -b - std::sqrt(b * b - c);
    EXPECT_NEAR(camera.at("hit").at("t").get<float>(), t, 1e-4f);
    const glint::Vec3 p = origin + direction * t, n = glint::normalize(p);
    EXPECT_NEAR(glint::dot(vec(camera.at("hit").at("normal")), n), 1.0f, 1e-5f);
    EXPECT_EQ(shadow.at("blocked"), false);
    EXPECT_EQ(shadow.at("light").at("type"), "point");
    const glint::Vec3 to_light = glint::Vec3(0, 3, 5) - p;
    const float expected_direct =
        0.5f * 10.0f * glint::dot(n, glint::normalize(to_light)) / glint::dot(to_light, to_light);
    EXPECT_NEAR(shadow.at("contribution")[0].get<float>(), expected_direct, 1e-5f);
    EXPECT_FLOAT_EQ(reflection.at("factor")[0].get<float>(), 0.5f);
    EXPECT_TRUE(reflection.at("hit").is_null());
    for (int ch = 0; ch < 3; ++ch) {
        const float background = std::array{0.2f, 0.3f, 0.4f}[ch];
        EXPECT_NEAR(reflection.at("contribution")[ch].get<float>(), 0.5f * background, 1e-6f);
        EXPECT_NEAR(camera.at("contribution")[ch].get<float>(), 0.0f, 1e-7f) << "no ambient light";
        const float sum = shadow.at("contribution")[ch].get<float>() + reflection.at("contribution")[ch].get<float>();
        EXPECT_NEAR(sum, image.at(4, 4, ch), 1e-6f) << "the rays add up to the rendered pixel (1 spp, box filter)";
    }
    fs::remove_all(dir);
}

TEST(Explain, GlassSplitsByFresnelsReflectance) {
    const fs::path dir = glint_test::temp_dir();
    // A clear glass ball filling the view: each camera ray splits into a reflection weighted
    // by Schlick's F(θ) and a refraction weighted by 1 − F.
    glint_test::write_file(dir / "glass.toml", R"([render]
width = 9
height = 9
max_depth = 1
[camera]
position = [0, 0, 5]
look_at = [0, 0, 0]
fov = 20
[background]
color = [0.2, 0.3, 0.4]
[[materials]]
name = "clear glass"
diffuse = 0
transparency = 1
ior = 1.5
[[objects]]
name = "ball"
type = "sphere"
center = [0, 0, 0]
radius = 1
material = "clear glass"
)");
    for (const char* pixel : {"4,4", "2,3", "1,4"}) {
        const json e = explain_json((dir / "glass.toml").string() + " --pixel " + pixel, dir);
        const json& rays = e.at("samples").at(0).at("rays");
        const json& camera = rays.at(0);
        ASSERT_FALSE(camera.at("hit").is_null()) << pixel;
        EXPECT_EQ(camera.at("hit").at("object_name"), "ball");
        EXPECT_EQ(camera.at("hit").at("material_name"), "clear glass");
        float cos_theta = 0;
        for (int i = 0; i < 3; ++i)
            cos_theta -= camera.at("direction")[i].get<float>() * camera.at("hit").at("normal")[i].get<float>();
        const float f0 = 0.04f;  // ((1.5 − 1) / (1.5 + 1))²
        const float fresnel = f0 + (1 - f0) * std::pow(1 - cos_theta, 5.0f);
        int reflections = 0, refractions = 0;
        for (const json& ray : rays) {
            if (ray.at("parent") != 0) continue;
            if (ray.at("kind") == "reflection") {
                ++reflections;
                EXPECT_NEAR(ray.at("factor")[0].get<float>(), fresnel, 1e-5f) << pixel;
            }
            if (ray.at("kind") == "refraction") {
                ++refractions;
                EXPECT_NEAR(ray.at("factor")[0].get<float>(), 1 - fresnel, 1e-5f) << pixel;
            }
        }
        EXPECT_EQ(reflections, 1) << pixel;
        EXPECT_EQ(refractions, 1) << pixel;
    }
    fs::remove_all(dir);
}

TEST(Explain, TextNamesObjectsMaterialsAndLights) {
    const fs::path dir = glint_test::temp_dir();
    const glint_test::CliResult r = run_cli(
        kCli, "explain " + (glint_test::kScenesDir / "whitted1980.toml").string() + " --pixel 320,200 --spp 1", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* expected :
         {"pixel (320, 200) of 640×480, 1 spp, whitted integrator, seed 0", "sample 0 at film (",
          "#0 camera ray: hits 'glass sphere' ('glass') at t = ", "#1 shadow ray to light #0 (point): ",
          "#2 reflection ray (factor ", "refraction ray (factor ", "the rays add up to "})
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
    fs::remove_all(dir);
}

TEST(Explain, OneSampleCanBeChosen) {
    const fs::path dir = glint_test::temp_dir();
    const json e =
        explain_json((glint_test::kScenesDir / "spheres.toml").string() + " --pixel 10,10 --spp 4 --sample 2", dir);
    ASSERT_EQ(e.at("samples").size(), 4u);
    for (const json& sample : e.at("samples"))
        EXPECT_EQ(sample.contains("rays"), sample.at("index") == 2) << sample.at("index");
    fs::remove_all(dir);
}

TEST(Explain, TheSameTreeOnOneThreadAsOnTwo) {
    // --threads bounds the whole process (the load and the build too), as for render; the
    // pixel's tree must not depend on it.
    const fs::path dir = glint_test::temp_dir();
    const std::string args = (glint_test::kScenesDir / "bunny_glass.toml").string() + " --pixel 300,260 --spp 4 --json";
    const glint_test::CliResult one = run_cli(kCli, "explain " + args + " --threads 1", dir);
    const glint_test::CliResult two = run_cli(kCli, "explain " + args + " --threads 2", dir);
    ASSERT_EQ(one.exit_code, 0) << one.err;
    ASSERT_EQ(two.exit_code, 0) << two.err;
    EXPECT_FALSE(json::parse(one.out).at("samples").empty());
    EXPECT_EQ(one.out, two.out);
    fs::remove_all(dir);
}

TEST(Explain, MistakesGetAReasonAndExitOne) {
    const fs::path dir = glint_test::temp_dir();
    const std::string scene = (glint_test::kScenesDir / "spheres.toml").string();
    const std::pair<std::string, std::string> cases[] = {
        {scene + " --pixel 640,0", "--pixel 640,0: outside the 640×480 image (columns 0 to 639, rows 0 to 479)"},
        {scene + " --pixel 3", "--pixel: expected X,Y (column and row from the top-left, whole numbers); got '3'"},
        {scene + " --pixel 3,-1", "--pixel: expected X,Y"},
        {scene + " --pixel 3,4 --spp 4 --sample 4",
         "--sample: expected a sample of this render's 4 per pixel, 0 to 3; got 4"},
        {scene + " --pixel 3,4 --spp 5", "--spp: expected a square number"},
        {scene + " --pixel 3,4 --threads -1", "--threads: expected 0 (all cores) or a thread count up to 1024; got -1"},
        {scene, "--pixel is required"},
    };
    for (const auto& [args, expected] : cases) {
        const glint_test::CliResult r = run_cli(kCli, "explain " + args, dir);
        EXPECT_EQ(r.exit_code, 1) << args;
        EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
    }
    fs::remove_all(dir);
}
