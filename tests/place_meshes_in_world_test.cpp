// Scene::place_meshes_in_world: a mesh that one still object alone places is carried into
// world space, and the prepared scene answers every ray as the placement did; what must stay
// a placement (instances, mirrors, moving objects, float overflow) stays one, and a mesh
// held elsewhere is never changed under its holder.

#include "glint/geometry/triangle_mesh.h"
#include "glint/materials/texture.h"

#include "glint/math/animated_transform.h"
#include "glint/scene/render_scene.h"
#include "uv_sphere_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

namespace glint {
namespace {

/// The test sphere, fine enough that interpolating normals in world or object space differs
/// by little.
MeshData uv_sphere_with_normals() { return glint_test::uv_sphere_mesh(48, 96); }

/// Turned, squashed unevenly and moved: normals must turn by the inverse transpose.
Transform placement() {
    return Transform::translate({3.0f, -1.0f, 2.0f}) * Transform::rotate(30.0f, {1.0f, 2.0f, 3.0f}) *
           Transform::scale({2.0f, 0.5f, 1.5f});
}

/// A scene with one textured material, so that hits carry their texture coordinates, tangents
/// and curvature (RenderScene::reads_texture_coordinates), which the tests compare too.
Scene scene_with_material() {
    static const CheckerTexture checks(Color(1.0f), Color(0.0f), 4.0f);
    Scene scene;
    Material textured;
    textured.texture = &checks;
    scene.add_material(textured);
    return scene;
}

/// The scene with the mesh placed by `t` alone (carried into world space) and the scene
/// with it placed twice (an instance, the reference) answer the same rays alike. Shading
/// normals and tangents are interpolated between the corners' vectors: in world space after
/// the carry, before the transform for an instance. Where the transform scales unevenly the
/// two differ by an amount that shrinks with the square of the triangles' size, hence
/// `vector_dot`; curvature, scaled by the area ratio for an instance, is compared only when
/// `t` scales evenly.
void expect_same_answers(const Transform& t, float vector_dot, bool compare_curvature) {
    Scene alone = scene_with_material();
    alone.add_object(std::make_shared<TriangleMesh>(uv_sphere_with_normals()), 0, t);
    const RenderScene placed(std::move(alone));
    ASSERT_FALSE(placed.description().objects()[0].has_transform);

    Scene twice = scene_with_material();
    const auto shared = std::make_shared<TriangleMesh>(uv_sphere_with_normals());
    twice.add_object(shared, 0, t);
    twice.add_object(shared, 0, Transform::translate({100.0f, 0.0f, 0.0f}) * t);
    const RenderScene instanced(std::move(twice));
    ASSERT_TRUE(instanced.description().objects()[0].has_transform);

    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        // From outside, toward the inner half of the sphere (no grazing rays), away from the
        // poles (where the tangents turn fastest).
        const Vec3 from = t.point(normalize(Vec3(u(rng), 0.3f * u(rng), u(rng))) * 4.0f);
        const Vec3 to = t.point(Vec3(u(rng), u(rng), u(rng)) * 0.3f);
        Ray a(from, normalize(to - from)), b = a;
        Hit ha, hb;
        ASSERT_TRUE(placed.intersect(a, ha)) << "ray " << i;
        ASSERT_TRUE(instanced.intersect(b, hb)) << "ray " << i;
        ASSERT_EQ(hb.object, 0u);
        EXPECT_NEAR(ha.t, hb.t, 1e-5f * hb.t) << "ray " << i;
        const SurfaceInteraction sa = placed.interaction(a, ha), sb = instanced.interaction(b, hb);
        EXPECT_LT(length(sa.p - sb.p), 1e-5f * length(sb.p) + 1e-6f) << "ray " << i;
        EXPECT_GT(dot(sa.geometric_normal, sb.geometric_normal), 1.0f - 1e-5f) << "ray " << i;
        EXPECT_GT(dot(sa.shading_normal, sb.shading_normal), vector_dot) << "ray " << i;
        EXPECT_GT(dot(normalize(sa.tangent), normalize(sb.tangent)), vector_dot) << "ray " << i;
        EXPECT_EQ(sa.tangent_sign, sb.tangent_sign) << "ray " << i;
        EXPECT_EQ(sa.front_face, sb.front_face) << "ray " << i;
        EXPECT_NEAR(sa.uv.x, sb.uv.x, 1e-4f) << "ray " << i;
        EXPECT_NEAR(sa.uv.y, sb.uv.y, 1e-4f) << "ray " << i;
        if (compare_curvature) {
            EXPECT_NEAR(sa.curvature, sb.curvature, 1e-3f * sb.curvature) << "ray " << i;
        }
    }
}

TEST(PlaceMeshesInWorld, ASinglyPlacedMeshAnswersEveryRayAsItsPlacementDid) {
    // Scaled evenly (as the POV-Ray dragon is) and turned.
    expect_same_answers(Transform::translate({0.06f, -0.527f, 0.0f}) * Transform::rotate(40.0f, {0.0f, 1.0f, 0.0f}) *
                            Transform::scale({10.0f, 10.0f, 10.0f}),
                        1.0f - 1e-6f, true);
    // Squashed unevenly too: normals must turn by the inverse transpose.
    expect_same_answers(placement(), 1.0f - 2e-5f, false);
}

TEST(PlaceMeshesInWorld, InstancesMirrorsAndMovingObjectsKeepTheirPlacements) {
    Scene scene = scene_with_material();
    const auto shared = std::make_shared<TriangleMesh>(uv_sphere_with_normals());
    scene.add_object(shared, 0, placement());
    scene.add_object(shared, 0, Transform::translate({10.0f, 0.0f, 0.0f}));
    scene.add_object(std::make_shared<TriangleMesh>(uv_sphere_with_normals()), 0,
                     Transform::scale({-1.0f, 1.0f, 1.0f}));  // mirrored
    const uint32_t moving = scene.add_object(std::make_shared<TriangleMesh>(uv_sphere_with_normals()), 0);
    scene.set_motion(moving, AnimatedTransform({MotionKey{0.0f, Transform::translate({0.0f, 5.0f, 0.0f})},
                                                MotionKey{1.0f, Transform::translate({1.0f, 5.0f, 0.0f})}}));
    scene.add_object(std::make_shared<TriangleMesh>(uv_sphere_with_normals()), 0, placement());  // this one goes
    scene.place_meshes_in_world();
    const std::vector<SceneObject>& objects = scene.objects();
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(objects[i].has_transform) << "object " << i;
    EXPECT_EQ(objects[0].shape.get(), objects[1].shape.get());
    EXPECT_NEAR(objects[0].shape->bounds().hi.x, 1.0f, 1e-6f);  // still in object space
    EXPECT_FALSE(objects[4].has_transform);
    EXPECT_GT(objects[4].shape->bounds().lo.x, 0.5f);  // moved by (3, -1, 2)
}

TEST(PlaceMeshesInWorld, AMeshHeldElsewhereIsCopiedNotChanged) {
    const auto mesh = std::make_shared<TriangleMesh>(uv_sphere_with_normals());
    Scene scene = scene_with_material();
    scene.add_object(mesh, 0, placement());
    scene.place_meshes_in_world();
    const SceneObject& o = scene.objects()[0];
    EXPECT_FALSE(o.has_transform);
    ASSERT_NE(o.shape.get(), mesh.get());
    const MeshData original = uv_sphere_with_normals();
    const Transform t = placement();
    const auto& copy = static_cast<const TriangleMesh&>(*o.shape);
    for (size_t i = 0; i < original.positions.size(); ++i) {
        ASSERT_EQ(mesh->data().positions[i], original.positions[i]) << "vertex " << i;
        ASSERT_EQ(copy.data().positions[i], t.point(original.positions[i])) << "vertex " << i;
    }
}

TEST(PlaceMeshesInWorld, APlacementBeyondFloatRangeStaysAPlacement) {
    MeshData far;
    far.positions = {{0.0f, 0.0f, 0.0f}, {1e30f, 0.0f, 0.0f}, {0.0f, 1e30f, 0.0f}};
    far.indices = {0, 1, 2};
    Scene scene = scene_with_material();
    scene.add_object(std::make_shared<TriangleMesh>(std::move(far)), 0, Transform::scale({1e10f, 1e10f, 1e10f}));
    scene.place_meshes_in_world();
    const SceneObject& o = scene.objects()[0];
    EXPECT_TRUE(o.has_transform);
    EXPECT_EQ(static_cast<const TriangleMesh&>(*o.shape).data().positions[1].x, 1e30f);
}

}  // namespace
}  // namespace glint
