// The TOML scene format's objects and shapes: named shapes shared between objects, transforms
// in the order written, per-vertex materials, heightfields, and the spheres files against the
// built-in scene.

#include "glint/geometry/heightfield.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/default_scene.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"
#include "toml_text.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace glint {
namespace {

constexpr std::string_view kGeometry = R"(
[[materials]]
name = "a"
[[materials]]
name = "b"
[[materials]]
name = "c"
[[shapes]]
name = "ball"
type = "sphere"
radius = 1
[[objects]]
shape = "ball"
material = "a"
transform = { scale = 2, translate = [1, 0, 0] }
[[objects]]
shape = "ball"
material = "b"
transform = [{ translate = [1, 0, 0] }, { scale = 2 }]
[[objects]]
type = "triangle"
vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
materials = ["a", "b", "c"]
[[objects]]
type = "mesh"
positions = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
indices = [0, 1, 2, 0, 2, 3]
uvs = [[0, 0], [1, 0], [1, 1], [0, 1]]
material = "c"
[[objects]]
type = "plane"
size = [4, 2]
material = "a"
transform = { rotate = [90, 0, 0] }
[[objects]]
type = "box"
min = [-1, -1, -1]
max = [1, 1, 1]
material = "b"
[[objects]]
type = "heightfield"
resolution = [3, 2]
min = [0, 0]
max = [2, 1]
height = 1
heights = [[0, 1, 2], [3, 4, 5]]
waves = [{ amplitude = 0.5, wavelength = 4 }]
material = "c"
)";

TEST(TomlScene, ObjectsAndSharedShapes) {
    const LoadedScene s = load(kGeometry);
    const auto& objects = s.scene.objects();
    ASSERT_EQ(objects.size(), 7u);
    EXPECT_EQ(objects[0].shape, objects[1].shape) << "objects placing one named shape share it (instancing)";
    EXPECT_EQ(objects[0].material, 0u);
    EXPECT_EQ(objects[1].material, 1u);
    EXPECT_EQ(objects[4].shape->type_name(), "quad");
    EXPECT_EQ(objects[5].shape->type_name(), "box");
    const auto* mesh = dynamic_cast<const TriangleMesh*>(objects[3].shape.get());
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(mesh->triangle_count(), 2u);
    EXPECT_EQ(mesh->data().uvs.size(), 4u);
    EXPECT_EQ(objects[3].material, 2u);
}

TEST(TomlScene, TransformTableIsScaleRotateTranslateAndListIsInOrder) {
    const LoadedScene s = load(kGeometry);
    // Table: scale 2 then translate → (1,0,0) ↦ (3,0,0). List: translate then scale → (4,0,0).
    EXPECT_EQ(s.scene.objects()[0].world_from_object.point(Vec3(1, 0, 0)), Vec3(3, 0, 0));
    EXPECT_EQ(s.scene.objects()[1].world_from_object.point(Vec3(1, 0, 0)), Vec3(4, 0, 0));
    // Euler x = 90°: the plane's +y normal turns to +z.
    const Vec3 n = s.scene.objects()[4].world_from_object.vector(Vec3(0, 1, 0));
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    EXPECT_NEAR(n.y, 0.0f, 1e-6f);
}

TEST(TomlScene, TrianglePerVertexMaterials) {
    const LoadedScene s = load(kGeometry);
    const auto* tri = dynamic_cast<const TriangleMesh*>(s.scene.objects()[2].shape.get());
    ASSERT_NE(tri, nullptr);
    EXPECT_EQ(tri->data().vertex_materials, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(TomlScene, HeightfieldAddsGridHeightsAndWaves) {
    const LoadedScene s = load(kGeometry);
    const auto* hf = dynamic_cast<const Heightfield*>(s.scene.objects()[6].shape.get());
    ASSERT_NE(hf, nullptr);
    // Vertex (i=1, j=1) sits at x = 1: base 1 + grid 4 + 0.5·sin(2π·1/4).
    EXPECT_NEAR(hf->height(1, 1), 1.0f + 4.0f + 0.5f, 1e-5f);
    EXPECT_NEAR(hf->height(0, 0), 1.0f, 1e-5f);
}

TEST(TomlScene, SpheresFileMatchesTheBuiltInScene) {
    for (const bool refraction : {false, true}) {
        const LoadedScene file =
            load_toml_scene(glint_test::kScenesDir / (refraction ? "spheres_refraction.toml" : "spheres.toml"));
        const Scene built_in = make_spheres_scene(refraction);
        ASSERT_EQ(file.scene.objects().size(), built_in.objects().size());
        ASSERT_EQ(file.scene.materials().size(), built_in.materials().size());
        for (std::size_t i = 0; i < built_in.materials().size(); ++i) {
            const Material &a = file.scene.material(uint32_t(i)), &b = built_in.material(uint32_t(i));
            EXPECT_NEAR(a.diffuse.r, b.diffuse.r, 1e-6f) << "material " << i;
            EXPECT_NEAR(a.diffuse.g, b.diffuse.g, 1e-6f) << "material " << i;
            EXPECT_NEAR(a.diffuse.b, b.diffuse.b, 1e-6f) << "material " << i;
            EXPECT_EQ(a.ambient == a.diffuse, b.ambient == b.diffuse);
            EXPECT_NEAR(a.reflectivity.r, b.reflectivity.r, 1e-6f);
            EXPECT_EQ(a.transparency, b.transparency);
            EXPECT_EQ(a.ior, b.ior);
            EXPECT_EQ(a.specular, b.specular);
            EXPECT_EQ(a.shininess, b.shininess);
        }
        for (std::size_t i = 0; i < built_in.objects().size(); ++i) {
            EXPECT_EQ(file.scene.objects()[i].material, built_in.objects()[i].material) << "object " << i;
            EXPECT_EQ(file.scene.objects()[i].world_from_object, built_in.objects()[i].world_from_object)
                << "object " << i;
        }
        EXPECT_EQ(file.scene.lights().size(), built_in.lights().size());
        EXPECT_EQ(file.scene.ambient_light, built_in.ambient_light);
        EXPECT_EQ(file.scene.dielectric_shadows, built_in.dielectric_shadows);
        EXPECT_EQ(file.scene.background.color(), built_in.background.color());
        EXPECT_EQ(file.scene.camera.eye(), built_in.camera.eye());
    }
}

}  // namespace
}  // namespace glint
