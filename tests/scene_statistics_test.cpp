// What `glint info` reports about a scene: triangles of every kind of shape that stores
// them, counted once per shape and once per placement, and the textures a scene declares.

#include "glint/geometry/heightfield.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/materials/uv_transform_texture.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <memory>

namespace glint {
namespace {

TEST(SceneStatistics, CountsMeshAndHeightfieldTrianglesPerShapeAndPerPlacement) {
    Scene scene;
    scene.add_material(Material{});
    MeshData quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    auto mesh = std::make_shared<TriangleMesh>(std::move(quad));
    // 4 × 3 vertices: 3 × 2 cells of two triangles each.
    auto field = std::make_shared<Heightfield>(4, 3, std::vector<float>(12, 0.0f), Vec2(0, 0), Vec2(3, 2));
    scene.add_object(mesh, 0);
    scene.add_object(mesh, 0, Transform::translate({5, 0, 0}));
    scene.add_object(field, 0);
    scene.add_object(field, 0, Transform::translate({0, 5, 0}));
    scene.add_object(field, 0, Transform::translate({0, 9, 0}));
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), 0);  // no triangles
    const SceneStatistics s = RenderScene(std::move(scene)).statistics();
    EXPECT_EQ(s.unique_shapes, 3u);
    EXPECT_EQ(s.unique_triangles, 2u + 12u);
    EXPECT_EQ(s.instanced_triangles, 2u * 2u + 3u * 12u);
}

TEST(SceneStatistics, CountsDeclaredTexturesNotTheirViews) {
    Scene scene;
    const Texture* checker = scene.add_texture(std::make_unique<CheckerTexture>(Color(1.0f), Color(0.0f), 4.0f));
    scene.add_texture(std::make_unique<UvTransformTexture>(checker, Vec2(2.0f, 2.0f), Vec2(0.0f, 0.0f)));
    scene.add_texture(std::make_unique<CheckerTexture>(Color(0.5f), Color(0.0f), 2.0f));
    EXPECT_EQ(scene.texture_count(), 2u);
}

}  // namespace
}  // namespace glint
