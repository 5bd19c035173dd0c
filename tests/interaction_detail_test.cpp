// InteractionDetail: a shape asked for less (no texture coordinates) still gives every other
// field of the surface interaction, bit for bit as the full one, on every shape, from either
// side; and a prepared scene asks for less exactly when no material has a texture, so that
// untextured scenes skip the texture coordinates and textured ones always get them, placed
// objects included.

#include "glint/geometry/box.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/heightfield.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/materials/texture.h"
#include "glint/scene/render_scene.h"

#include "test_rays.h"
#include "uv_sphere_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace glint {
namespace {

/// Everything but what only texture lookups read (uv, dpdu, dpdv, tangent, curvature and
/// the footprint) agrees bit for bit.
void expect_same_geometry(const SurfaceInteraction& full, const SurfaceInteraction& reduced, const std::string& what) {
    EXPECT_EQ(full.p, reduced.p) << what;
    EXPECT_EQ(full.geometric_normal, reduced.geometric_normal) << what;
    EXPECT_EQ(full.shading_normal, reduced.shading_normal) << what;
    EXPECT_EQ(full.front_face, reduced.front_face) << what;
    EXPECT_EQ(full.vertex_color, reduced.vertex_color) << what;
    EXPECT_EQ(full.materials, reduced.materials) << what;
    EXPECT_EQ(full.material_weights, reduced.material_weights) << what;
    EXPECT_EQ(full.blends_materials, reduced.blends_materials) << what;
}

/// The test sphere with vertex colours and per-vertex materials as well: every field a mesh
/// can set.
MeshData uv_sphere() {
    constexpr int kRings = 12, kSegments = 24;
    MeshData m = glint_test::uv_sphere_mesh(kRings, kSegments);
    for (int r = 0; r <= kRings; ++r)
        for (int s = 0; s <= kSegments; ++s) {
            m.colors.push_back(Color(float(s) / kSegments, float(r) / kRings, 0.5f));
            m.vertex_materials.push_back(uint32_t(s % 2));
        }
    return m;
}

std::shared_ptr<Shape> bumpy_heightfield() {
    constexpr uint32_t kN = 9;
    std::vector<float> heights;
    for (uint32_t j = 0; j < kN; ++j)
        for (uint32_t i = 0; i < kN; ++i) heights.push_back(0.3f * std::sin(float(i)) * std::cos(0.7f * float(j)));
    return std::make_shared<Heightfield>(kN, kN, std::move(heights), Vec2(-1.5f, -1.5f), Vec2(1.5f, 1.5f));
}

struct NamedShape {
    std::string name;
    std::shared_ptr<Shape> shape;
};

std::vector<NamedShape> every_shape() {
    auto mesh = std::make_shared<TriangleMesh>(uv_sphere());
    mesh->prepare();
    return {{"sphere", std::make_shared<Sphere>(Vec3(0.3f, -0.2f, 0.1f), 1.3f)},
            {"disk", std::make_shared<Disk>(Vec3(0.1f, 0.2f, 0.0f), Vec3(0.2f, 1.0f, 0.1f), 1.5f)},
            {"quad", std::make_shared<Quad>(Vec3(-1.0f, 0.0f, -1.0f), Vec3(2.0f, 0.0f, 0.0f), Vec3(0.0f, 0.3f, 2.0f))},
            {"box", std::make_shared<Box>(Vec3(-1.0f, -0.5f, -0.8f), Vec3(1.0f, 0.7f, 0.9f))},
            {"heightfield", bumpy_heightfield()},
            {"mesh", mesh}};
}

TEST(InteractionDetail, WithoutTextureCoordinatesEveryOtherFieldIsTheFullOnesOnEveryShape) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> near_centre(-0.4f, 0.4f);
    for (const NamedShape& s : every_shape()) {
        int hits = 0, back_faces = 0;
        for (int i = 0; i < 2000; ++i) {
            // Half from outside toward the middle, half from inside outward (back faces).
            const Vec3 inside(near_centre(rng), near_centre(rng), near_centre(rng));
            const Vec3 outside = glint_test::random_unit_vector(rng) * 4.0f;
            const Ray ray =
                i % 2 == 0 ? Ray(outside, inside - outside) : Ray(inside, glint_test::random_unit_vector(rng));
            Ray r = ray;
            Hit hit;
            if (!s.shape->intersect(r, hit)) continue;
            ++hits;
            SurfaceInteraction full, reduced;
            s.shape->interaction(ray, hit, full, InteractionDetail::Full);
            s.shape->interaction(ray, hit, reduced, InteractionDetail::WithoutTextureCoordinates);
            back_faces += full.front_face ? 0 : 1;
            expect_same_geometry(full, reduced, s.name + ", ray " + std::to_string(i));
        }
        EXPECT_GT(hits, 400) << s.name;
        EXPECT_GT(back_faces, 50) << s.name;
    }
}

/// A scene of every shape, each placed by a transform that turns and squashes it (so that
/// RenderScene::interaction takes the placement path), with material 0 textured in `slot`
/// (null for none).
Scene placed_shapes(const Texture* Material::*slot, const Texture& texture) {
    Scene scene;
    Material m;
    if (slot) m.*slot = &texture;
    scene.add_material(m);
    scene.add_material(Material{});
    const Transform t = Transform::translate({0.2f, 0.1f, -0.3f}) * Transform::rotate(25.0f, {1.0f, 2.0f, 3.0f}) *
                        Transform::scale({1.2f, 0.8f, 1.0f});
    float x = -7.5f;
    for (const NamedShape& s : every_shape()) {
        scene.add_object(s.shape, 0, Transform::translate({x, 0.0f, 0.0f}) * t);
        x += 3.0f;
    }
    return scene;
}

TEST(InteractionDetail, AnUntexturedSceneGivesEveryHitTheGeometryATexturedOneGives) {
    const CheckerTexture checks(Color(1.0f), Color(0.0f), 4.0f);
    const RenderScene plain(placed_shapes(nullptr, checks));
    const RenderScene textured(placed_shapes(&Material::texture, checks));
    ASSERT_FALSE(plain.reads_texture_coordinates());
    ASSERT_TRUE(textured.reads_texture_coordinates());
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> along(-8.0f, 8.0f);
    int hits = 0, textured_uvs = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 target(along(rng), 0.0f, 0.0f);
        const Vec3 origin = target + glint_test::random_unit_vector(rng) * 5.0f;
        const Ray ray(origin, target - origin);
        Ray a = ray, b = ray;
        Hit hit_plain, hit_textured;
        const bool found = plain.intersect(a, hit_plain);
        ASSERT_EQ(found, textured.intersect(b, hit_textured));
        if (!found) continue;
        ++hits;
        const SurfaceInteraction reduced = plain.interaction(a, hit_plain);
        const SurfaceInteraction full = textured.interaction(b, hit_textured);
        expect_same_geometry(full, reduced, "ray " + std::to_string(i));
        textured_uvs += full.uv.x != 0.0f || full.uv.y != 0.0f ? 1 : 0;
    }
    EXPECT_GT(hits, 1000);
    // The textured scene's hits have their texture coordinates: the placement path keeps them.
    EXPECT_GT(textured_uvs, hits * 9 / 10);
}

TEST(InteractionDetail, EveryTextureOfAMaterialMakesTheSceneReadTextureCoordinates) {
    const CheckerTexture checks(Color(1.0f), Color(0.0f), 4.0f);
    for (const Texture* Material::*slot : {&Material::texture, &Material::emission_texture, &Material::normal_texture,
                                           &Material::alpha_texture, &Material::metallic_roughness_texture}) {
        const RenderScene scene(placed_shapes(slot, checks));
        EXPECT_TRUE(scene.reads_texture_coordinates());
    }
}

}  // namespace
}  // namespace glint
