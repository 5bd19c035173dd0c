// The type tables of the scene language (scene_format/registry.h): every registered type
// can be written in a scene file and does what its kind promises, and the names in
// messages are the table's. A type added to a table without an example here fails the
// first test, so each new type arrives with a scene that exercises it.
#include "toml_text.h"

#include "glint/scene/scene.h"
#include "glint/scene_format/registry.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace glint {
namespace {

const char* const kMaterial = "[[materials]]\nname = \"m\"\n";

/// The smallest table body that builds each type (without its `type` line).
const std::map<std::string_view, std::string> kShapeExamples{
    {"sphere", "radius = 1\n"},
    {"triangle", "vertices = [[0, 0, 0], [1, 0, 0], [0.5, 1, 0]]\n"},
    {"mesh", "positions = [[0, 0, 0], [1, 0, 0], [0.5, 1, 0]]\nindices = [0, 1, 2]\n"},
    {"quad", "corner = [0, 0, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, -1]\n"},
    {"plane", "size = 2\n"},
    {"box", "min = [0, 0, 0]\nmax = [1, 1, 1]\n"},
    {"heightfield", "resolution = [2, 2]\nmin = [0, 0]\nmax = [1, 1]\n"},
    {"disk", "radius = 1\n"},
};

const std::map<std::string_view, std::string> kLightExamples{
    {"point", "position = [0, 2, 0]\n"},
    {"directional", "direction = [0, -1, 0]\n"},
    {"spot", "position = [0, 2, 0]\ndirection = [0, -1, 0]\n"},
    {"sphere", "center = [0, 2, 0]\nradius = 0.5\n"},
    {"quad", "corner = [0, 2, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\n"},
    {"disk", "center = [0, 2, 0]\nradius = 0.5\n"},
};

const std::map<std::string_view, std::string> kTextureExamples{
    {"image", "file = \"assets/kenney_prototype_orange_checker_1024.png\"\n"},
    {"checker", "scale = 4\n"},
};

const std::map<std::string_view, std::string> kMaterialExamples{
    {"standard", "diffuse = [0.5, 0.5, 0.5]\n"},
};

std::string typed(std::string_view section, std::string_view type, const std::string& body) {
    return "[[" + std::string(section) + "]]\ntype = \"" + std::string(type) + "\"\n" + body;
}

TEST(Registry, EveryShapeTypeBuildsAnObjectThatRaysHit) {
    for (const ShapeType& type : shape_types()) {
        ASSERT_TRUE(kShapeExamples.count(type.name)) << "add an example of shape '" << type.name << "' here";
        LoadedScene s = load(std::string(kMaterial) + typed("objects", type.name, kShapeExamples.at(type.name)) +
                             "material = \"m\"\n");
        ASSERT_EQ(s.scene.objects().size(), 1u) << type.name;
        const RenderScene prepared(std::move(s.scene));
        // Every example holds the centre of its bounds: a ray from afar towards it hits.
        const Vec3 target = prepared.bounds().center();
        const Vec3 origin = target + Vec3(1.0f, 2.0f, 3.0f) * 10.0f;
        Ray ray(origin, target - origin);
        Hit hit;
        EXPECT_TRUE(prepared.intersect(ray, hit)) << type.name;
    }
}

TEST(Registry, EveryLightTypeLightsAPointBelowIt) {
    for (const LightType& type : light_types()) {
        ASSERT_TRUE(kLightExamples.count(type.name)) << "add an example of light '" << type.name << "' here";
        LoadedScene s = load(typed("lights", type.name, kLightExamples.at(type.name)));
        const RenderScene prepared(std::move(s.scene));
        ASSERT_EQ(prepared.all_lights().size(), 1u) << type.name;
        const LightSample ls = prepared.all_lights()[0]->sample(Vec3(0.0f), Vec2(0.3f, 0.6f));
        EXPECT_FALSE(ls.radiance.is_black()) << type.name;
        EXPECT_GT(ls.direction.y, 0.0f) << type.name << ": the light is above the point";
    }
}

TEST(Registry, EveryTextureTypeVariesOverTheSurface) {
    for (const TextureType& type : texture_types()) {
        ASSERT_TRUE(kTextureExamples.count(type.name)) << "add an example of texture '" << type.name << "' here";
        const LoadedScene s = load(typed("textures", type.name, kTextureExamples.at(type.name)) +
                                   "name = \"t\"\n[[materials]]\nname = \"m\"\ntexture = \"t\"\n");
        const Texture* t = s.scene.material(0).texture;
        ASSERT_NE(t, nullptr) << type.name;
        EXPECT_EQ(t->type_name(), type.name);
        // Both examples are checkerboards: over a grid of uv, more than one colour shows.
        const Color first = t->evaluate(Vec2(0.0f, 0.0f), Vec3(0.0f));
        bool varies = false;
        for (int i = 0; i < 16 && !varies; ++i)
            for (int j = 0; j < 16 && !varies; ++j)
                varies = t->evaluate(Vec2((i + 0.5f) / 16.0f, (j + 0.5f) / 16.0f), Vec3(0.0f)) != first;
        EXPECT_TRUE(varies) << type.name;
    }
}

TEST(Registry, EveryMaterialTypeReadsItsKeys) {
    for (const MaterialType& type : material_types()) {
        ASSERT_TRUE(kMaterialExamples.count(type.name)) << "add an example of material '" << type.name << "' here";
        const LoadedScene s = load(typed("materials", type.name, kMaterialExamples.at(type.name)) + "name = \"m\"\n");
        ASSERT_EQ(s.scene.materials().size(), 1u) << type.name;
        EXPECT_EQ(s.scene.material(0).name, "m");
        EXPECT_EQ(s.scene.material(0).diffuse, Color(0.5f)) << type.name;
    }
}

TEST(Registry, MaterialTypeDefaultsToStandardAndUnknownOnesListTheTable) {
    EXPECT_NO_THROW((void)load("[[materials]]\nname = \"m\"\n"));
    expect_error("[[materials]]\nname = \"m\"\ntype = \"standrad\"\n", "test.toml:3:8:",
                 {"materials[0].type", "\"standard\"", "did you mean 'standard'"});
}

/// `"name"`, as choice lists quote it.
std::string quoted(std::string_view name) {
    std::string q = "\"";
    q += name;
    q += '"';
    return q;
}

TEST(Registry, UnknownTypesNameEveryTypeOfTheTable) {
    const std::string message = error_of(std::string(kMaterial) + "[[objects]]\ntype = \"cylinder\"\nmaterial = \"m\"\n");
    for (const ShapeType& type : shape_types())
        EXPECT_NE(message.find(quoted(type.name)), std::string::npos) << message;
    const std::string light = error_of("[[lights]]\ntype = \"area\"\n");
    for (const LightType& type : light_types())
        EXPECT_NE(light.find(quoted(type.name)), std::string::npos) << light;
}

}  // namespace
}  // namespace glint
