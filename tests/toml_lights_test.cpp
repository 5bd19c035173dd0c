// Area lights, emissive objects, integrators and filters in scene files; their mistakes;
// and glass that renders the same whichever way its surface is wound.

#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/render_scene.h"
#include "toml_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

constexpr std::string_view kLight = "[[lights]]\n";

TEST(TomlAreaLights, SphereQuadAndDiskBecomeLightsAndObjects) {
    LoadedScene s = load(std::string(kLight) + "type = \"sphere\"\ncenter = [0, 3, 0]\nradius = 0.5\nradiance = 4\n" +
                         std::string(kLight) +
                         "type = \"quad\"\ncorner = [-1, 2, -1]\nedge_u = [2, 0, 0]\nedge_v = [0, 0, 2]\n"
                         "radiance = [1, 2, 3]\ntwo_sided = true\n" +
                         std::string(kLight) + "type = \"disk\"\ncenter = [0, 1, 0]\nradius = 0.25\n");
    const RenderScene prepared(std::move(s.scene));
    ASSERT_EQ(prepared.description().objects().size(), 3u);
    ASSERT_EQ(prepared.area_lights().size(), 3u);
    EXPECT_EQ(prepared.area_lights()[0]->radiance(), Color(4.0f));
    EXPECT_EQ(prepared.area_lights()[1]->radiance(), Color(1, 2, 3));
    EXPECT_TRUE(prepared.area_lights()[1]->two_sided());
    EXPECT_FALSE(prepared.area_lights()[2]->two_sided());
    // The disk faces down by default: it lights a point under it, not one above.
    const Light& disk = *prepared.area_lights()[2];
    EXPECT_FALSE(disk.sample(Vec3(0, 0, 0), Vec2(0.3f, 0.6f)).radiance.is_black());
    EXPECT_TRUE(disk.sample(Vec3(0, 2, 0), Vec2(0.3f, 0.6f)).radiance.is_black());
    EXPECT_TRUE(s.warnings.empty());
}

TEST(TomlAreaLights, EmissiveObjectsAreLightsUnlessTheWorldSaysNo) {
    const std::string scene =
        "[[materials]]\nname = \"lamp\"\nemission = 2\n[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = "
        "\"lamp\"\n";
    LoadedScene lit = load(scene);
    const RenderScene prepared(std::move(lit.scene));
    EXPECT_EQ(prepared.area_lights().size(), 1u);
    EXPECT_TRUE(lit.warnings.empty()) << "an emissive object lights the scene: no 'unlit' warning";
    LoadedScene seen = load("[world]\nemission_lights = false\n" + scene);
    const RenderScene prepared2(std::move(seen.scene));
    EXPECT_TRUE(prepared2.area_lights().empty());
}

TEST(TomlAreaLights, Mistakes) {
    expect_error(std::string(kLight) + "type = \"sphere\"\nradius = 0\n",
                 "test.toml:3:10:", {"lights[0].radius", "expected a positive radius"});
    expect_error(std::string(kLight) + "type = \"disk\"\nradius = -1\n",
                 "test.toml:3:10:", {"expected a positive radius"});
    expect_error(std::string(kLight) + "type = \"quad\"\ncorner = [0, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [2, 0, 0]\n",
                 "test.toml:5:10:", {"edge_v", "positive area"});
    expect_error(std::string(kLight) + "type = \"sphere\"\nradius = 1\nradiance = 0\n",
                 "test.toml:4:12:", {"lights[0].radiance", "emits nothing"});
    expect_error(std::string(kLight) + "type = \"point\"\nposition = [0, 1, 0]\nintensity = [0, 0, 0]\n",
                 "test.toml:4:13:", {"lights[0].intensity", "emits nothing"});
    expect_error(std::string(kLight) + "type = \"sphere\"\nradius = 1\nmaterial = \"lamp\"\n",
                 "test.toml:4:1:", {"unknown key 'material'"});
    expect_error(
        "[[materials]]\nname = \"lamp\"\nemission = 2\n[[objects]]\ntype = \"sphere\"\nradius = 1\n"
        "material = \"lmap\"\n",
        "test.toml:7:12:", {"objects[0].material", "did you mean 'lamp'?"});
}

TEST(TomlRender, IntegratorFilterAndLightSamples) {
    const LoadedScene s = load(
        "[render]\nintegrator = \"path\"\nfilter = \"mitchell\"\nfilter_radius = 1.5\nlight_samples = 9\nmis = "
        "\"balance\"\n");
    EXPECT_EQ(s.settings.integrator, "path");
    EXPECT_EQ(s.settings.filter, PixelFilter::Mitchell);
    EXPECT_EQ(s.settings.filter_radius, 1.5f);
    EXPECT_EQ(s.settings.light_samples, 9u);
    EXPECT_EQ(s.settings.mis, MisHeuristic::Balance);
    expect_error("[render]\nintegrator = \"pathtracer\"\n",
                 "test.toml:2:14:", {"render.integrator", "whitted", "path"});
    expect_error("[render]\nfilter = \"lanczos\"\n", "test.toml:2:10:", {"render.filter", "gaussian", "mitchell"});
    expect_error("[render]\nfilter_radius = 0\n", "test.toml:2:17:", {"render.filter_radius"});
    expect_error("[render]\nlight_samples = 0\n", "test.toml:2:17:", {"render.light_samples", "from 1 to 1024"});
}

TEST(TomlRender, GlossySamplesAndRoughness) {
    EXPECT_EQ(load("").settings.glossy_samples, 4u);
    EXPECT_EQ(load("[render]\nglossy_samples = 16\n").settings.glossy_samples, 16u);
    expect_error("[render]\nglossy_samples = 0\n", "test.toml:2:18:", {"render.glossy_samples", "from 1 to 1024"});
    expect_error("[render]\nglossy_samples = 1025\n", "test.toml:2:18:", {"render.glossy_samples", "from 1 to 1024"});
    for (const char* bad : {"1.5", "-0.1"})
        expect_error(std::string("[[materials]]\nname = \"m\"\nroughness = ") + bad + "\n",
                     "test.toml:3:13:", {"materials[0].roughness", "a roughness from 0 to 1"});
}

/// A water quad (index 1.33) over a checker floor under a point light, seen from above.
std::string water_scene(bool normal_up) {
    const std::string edges =
        normal_up ? "edge_u = [4, 0, 0]\nedge_v = [0, 0, -4]\n" : "edge_u = [0, 0, -4]\nedge_v = [4, 0, 0]\n";
    return "[camera]\nposition = [0, 3, 3]\nlook_at = [0, 0, 0]\nfov = 40\n"
           "[background]\ncolor = [0.5, 0.7, 1.0]\n"
           "[[textures]]\nname = \"tiles\"\ntype = \"checker\"\nscale = 4\n"
           "[[materials]]\nname = \"floor\"\ndiffuse = 0.8\ntexture = \"tiles\"\n"
           "[[materials]]\nname = \"water\"\nrefraction_index = 1.33\n"
           "[[lights]]\ntype = \"point\"\nposition = [1, 5, 2]\n"
           "[[objects]]\ntype = \"plane\"\nsize = 4\nmaterial = \"floor\"\n"
           "[[objects]]\ntype = \"quad\"\ncorner = [-2, 0.5, 2]\n" +
           edges + "material = \"water\"\n";
}

TEST(Dielectrics, WaterLooksTheSameWhicheverWayItsQuadIsWound) {
    RenderSettings settings;
    settings.width = settings.height = 24;
    auto render = [&](bool normal_up) {
        LoadedScene s = load(water_scene(normal_up));
        const RenderScene prepared(std::move(s.scene));
        Film film(settings.width, settings.height);
        make_integrator(settings)->render(prepared, settings, film);
        return film;
    };
    const Film up = render(true), down = render(false);
    int refracted_pixels = 0;
    for (uint32_t y = 0; y < settings.height; ++y)
        for (uint32_t x = 0; x < settings.width; ++x) {
            EXPECT_NEAR(up.at(x, y).r, down.at(x, y).r, 1e-5f) << x << "," << y;
            EXPECT_NEAR(up.at(x, y).b, down.at(x, y).b, 1e-5f) << x << "," << y;
            // Seen through the water, the floor is mostly grey-to-white, not the sky's blue.
            if (up.at(x, y).r > 0.3f && up.at(x, y).b < up.at(x, y).r * 1.3f) ++refracted_pixels;
        }
    EXPECT_GT(refracted_pixels, 100) << "the floor must be seen through the water";
}

TEST(Filter, WeightsAndOffsetsFollowTheFilter) {
    // Filter importance sampling: E[w·g(offset)] over stratified u equals ∫f·g / ∫f|…
    // checked here on g = 1 (mean weight = ∫f) and on the filter's support and symmetry.
    for (const PixelFilter kind : {PixelFilter::Box, PixelFilter::Tent, PixelFilter::Gaussian, PixelFilter::Mitchell}) {
        const Filter filter(kind);
        double weight_sum = 0.0, x_sum = 0.0;
        constexpr int kGrid = 64;
        for (int j = 0; j < kGrid; ++j)
            for (int i = 0; i < kGrid; ++i) {
                const FilterSample s = filter.sample(Vec2((float(i) + 0.5f) / kGrid, (float(j) + 0.5f) / kGrid));
                EXPECT_LE(std::abs(s.offset.x), filter.radius() + 1e-5f);
                EXPECT_LE(std::abs(s.offset.y), filter.radius() + 1e-5f);
                weight_sum += s.weight;
                x_sum += s.weight * s.offset.x;
            }
        EXPECT_GT(weight_sum, 0.0) << filter_name(kind);
        EXPECT_NEAR(x_sum / weight_sum, 0.0, 1e-3) << filter_name(kind) << " is symmetric";
    }
    // Mitchell's negative lobes come back as negative weights.
    const Filter mitchell(PixelFilter::Mitchell);
    EXPECT_LT(mitchell.sample(Vec2(0.01f, 0.5f)).weight, 0.0f);
    EXPECT_LT(mitchell.evaluate(Vec2(1.7f, 0.0f)), 0.0f);
    EXPECT_THROW(Filter(PixelFilter::Gaussian, -1.0f), std::invalid_argument);
}

}  // namespace
}  // namespace glint
