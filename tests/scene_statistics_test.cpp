// What `glint info` reports about a scene: triangles of every kind of shape that stores
// them, counted once per shape and once per placement, and the textures a scene declares.

#include "glint/geometry/heightfield.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/scene.h"

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
    scene.prepare();
    const SceneStatistics s = scene.statistics();
    EXPECT_EQ(s.unique_shapes, 3u);
    EXPECT_EQ(s.unique_triangles, 2u + 12u);
    EXPECT_EQ(s.instanced_triangles, 2u * 2u + 3u * 12u);
}

/// A texture that looks up another one, as scene files' uv_scale and uv_offset do.
class View final : public Texture {
public:
    explicit View(const Texture* base) : base_(base) {}
    Color evaluate(const Vec2& uv, const Vec3& p) const override { return base_->evaluate(uv * 2.0f, p); }
    std::string_view type_name() const override { return base_->type_name(); }
    bool is_view() const override { return true; }

private:
    const Texture* base_;
};

TEST(SceneStatistics, CountsDeclaredTexturesNotTheirViews) {
    Scene scene;
    const Texture* checker = scene.add_texture(std::make_unique<CheckerTexture>(Color(1.0f), Color(0.0f), 4.0f));
    scene.add_texture(std::make_unique<View>(checker));
    scene.add_texture(std::make_unique<CheckerTexture>(Color(0.5f), Color(0.0f), 2.0f));
    EXPECT_EQ(scene.texture_count(), 2u);
}

}  // namespace
}  // namespace glint
