// Scenes that place one mesh file many times with [[objects]]: every placement is an
// instance of one mesh read once, whatever the file name is spelt as, and a mistake in the
// last of thousands of objects is still reported by its full name at its line.

#include "glint/scene/render_scene.h"
#include "toml_text.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>

namespace glint {
namespace {

constexpr int kPlacements = 3000;

/// `count` placements of the shared bunny, spelt three ways, each turned and moved along x.
std::string bunnies(int count, std::string_view last_axis = "[0, 1, 0]") {
    constexpr std::array<std::string_view, 3> kSpellings = {"assets/stanford_bunny.ply", "./assets/stanford_bunny.ply",
                                                            "assets/../assets/stanford_bunny.ply"};
    std::string text = "[[materials]]\nname = \"clay\"\n";
    for (int i = 0; i < count; ++i)
        text += fmt::format(
            "[[objects]]\ntype = \"mesh\"\nfile = \"{}\"\nmaterial = \"clay\"\n"
            "transform = {{ scale = 2, rotate = {{ axis = {}, degrees = {} }}, translate = [{}, 0, 0] }}\n",
            kSpellings[std::size_t(i) % kSpellings.size()], i + 1 == count ? last_axis : "[0, 1, 0]", i % 360, 3 * i);
    return text;
}

TEST(TomlInstancing, ThousandsOfPlacementsShareOneMesh) {
    const RenderScene scene(load(bunnies(kPlacements)).scene);
    const SceneStatistics stats = scene.statistics();
    EXPECT_EQ(stats.objects, std::size_t(kPlacements));
    EXPECT_EQ(stats.unique_shapes, 1u) << "three spellings of one file are one mesh";
    EXPECT_EQ(stats.instanced_triangles, stats.unique_triangles * kPlacements);

    // Each placement is where its transform puts it: a ray straight down through the
    // middle of placement i meets bunny i, scaled by 2 (the bunny stands 0.15 tall on y = 0.03).
    for (const int i : {0, 1, 2, 1234, kPlacements - 1}) {
        const Bounds3 box = scene.description().objects()[std::size_t(i)].world_bounds();
        EXPECT_NEAR(0.5f * (box.lo.x + box.hi.x), float(3 * i), 0.5f) << "placement " << i;
        EXPECT_NEAR(box.hi.y - box.lo.y, 2.0f * 0.1543f, 0.01f) << "placement " << i;
        Ray ray({float(3 * i), 10.0f, 0.5f * (box.lo.z + box.hi.z)}, {0, -1, 0});
        Hit hit;
        ASSERT_TRUE(scene.intersect(ray, hit)) << "placement " << i;
        EXPECT_EQ(hit.object, uint32_t(i));
    }
}

TEST(TomlInstancing, AMistakeInTheLastPlacementIsNamedAndLocated) {
    const std::string line = std::to_string(2 + 5 * kPlacements);
    expect_error(bunnies(kPlacements, "[0, 0, 0]"), "test.toml:" + line + ":",
                 {fmt::format("objects[{}].transform.rotate.axis", kPlacements - 1), "a non-zero axis"});
    expect_error(bunnies(kPlacements, "[0, \"up\", 0]"), "test.toml:" + line + ":",
                 {fmt::format("objects[{}].transform.rotate.axis[1] is the string \"up\"", kPlacements - 1)});
}

}  // namespace
}  // namespace glint
