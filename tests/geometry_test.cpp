#include "glint/geometry/box.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/math/offset_ray.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include "test_rays.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <memory>
#include <random>
#include <utility>

using namespace glint;

// ---- Sphere ---------------------------------------------------------------------------

TEST(Sphere, HitFromOutsideReturnsNearRoot) {
    const Sphere s({0, 0, 0}, 2.0f);
    Ray r({0, 0, -10}, {0, 0, 1});
    Hit h;
    ASSERT_TRUE(s.intersect(r, h));
    EXPECT_FLOAT_EQ(h.t, 8.0f);
    EXPECT_FLOAT_EQ(r.tmax, 8.0f);
    SurfaceInteraction si;
    s.interaction(r, h, si);
    EXPECT_NEAR(si.geometric_normal.z, -1.0f, 1e-6f);
    EXPECT_TRUE(si.front_face);
}

TEST(Sphere, MissAndBehind) {
    const Sphere s({0, 0, 0}, 1.0f);
    Ray miss({0, 1.01f, -5}, {0, 0, 1});
    Hit h;
    EXPECT_FALSE(s.intersect(miss, h));
    Ray behind({0, 0, 5}, {0, 0, 1});
    EXPECT_FALSE(s.intersect(behind, h));
    EXPECT_FALSE(s.occluded(behind));
}

TEST(Sphere, GrazingRayTouchesOnce) {
    const Sphere s({0, 0, 0}, 1.0f);
    Ray r({0, 1.0f, -5}, {0, 0, 1});
    Hit h;
    ASSERT_TRUE(s.intersect(r, h));
    EXPECT_NEAR(h.t, 5.0f, 1e-3f);
}

TEST(Sphere, FromInsideHitsFarRootBackFace) {
    const Sphere s({1, 1, 1}, 3.0f);
    Ray r({1, 1, 1}, {1, 0, 0});
    Hit h;
    ASSERT_TRUE(s.intersect(r, h));
    EXPECT_FLOAT_EQ(h.t, 3.0f);
    SurfaceInteraction si;
    s.interaction(r, h, si);
    EXPECT_FALSE(si.front_face);
}

TEST(Sphere, RespectsTRange) {
    const Sphere s({0, 0, 0}, 1.0f);
    Ray short_ray({0, 0, -5}, {0, 0, 1}, 0.0f, 3.9f);
    Hit h;
    EXPECT_FALSE(s.intersect(short_ray, h));
    EXPECT_FALSE(s.occluded(short_ray));
    Ray skip_near({0, 0, -5}, {0, 0, 1}, 4.5f, kInfinity);  // starts past the near root
    ASSERT_TRUE(s.intersect(skip_near, h));
    EXPECT_FLOAT_EQ(h.t, 6.0f);
}

TEST(Sphere, StableFarFromOrigin) {
    // The textbook b² - 4ac loses every digit here; the stable form does not.
    const Sphere s({0, 0, 0}, 1.0f);
    Ray r({0, 0, -1e4f}, {0, 0, 1});
    Hit h;
    ASSERT_TRUE(s.intersect(r, h));
    EXPECT_NEAR(h.t, 1e4f - 1.0f, 1e-2f);
}

TEST(Sphere, RejectsBadRadius) {
    EXPECT_THROW(Sphere({0, 0, 0}, -1.0f), std::invalid_argument);
    EXPECT_THROW(Sphere({0, 0, 0}, 0.0f), std::invalid_argument);
    EXPECT_THROW(Sphere({0, 0, 0}, std::nanf("")), std::invalid_argument);
}

TEST(Sphere, ReintersectFromOffsetOriginNeverHitsAgain) {
    // pbrt-v4's invariant: a ray leaving a convex shape outward never hits it again.
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.01f, 1000.0f);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const float radius = u(rng);
        const Sphere s(glint_test::random_unit_vector(rng) * u(rng), radius);
        Ray r(s.center() + glint_test::random_unit_vector(rng) * (radius * 3.0f), {});
        r.direction = normalize(s.center() - r.origin + glint_test::random_unit_vector(rng) * (radius * 0.5f));
        Hit h;
        if (!s.intersect(r, h)) continue;
        ++hits;
        SurfaceInteraction si;
        s.interaction(r, h, si);
        Vec3 out = glint_test::random_unit_vector(rng);
        if (dot(out, si.geometric_normal) < 0.0f) out = -out;
        Ray again(offset_ray_origin(si.p, si.geometric_normal), out);
        Hit h2;
        EXPECT_FALSE(s.intersect(again, h2)) << "radius " << radius;
    }
    // Every ray aims within half a radius of the centre, so all should hit: without
    // hits the invariant above would hold vacuously.
    EXPECT_EQ(hits, 1000);
}

// ---- Triangle (the watertight test every triangle goes through) --------------------------

namespace {

bool intersect_triangle(const Ray& ray, const Vec3& v0, const Vec3& v1, const Vec3& v2, TriangleHit& th) {
    return intersect_triangle_watertight(ray, WatertightRay(ray.direction), v0, v1, v2, th);
}

}  // namespace

TEST(Triangle, WatertightRayShearsAlongTheLargestAxis) {
    // Directions along, between and across the axes with both signs, ties included.
    const float values[] = {-2.0f, -1.0f, -0.5f, 0.0f, 0.5f, 1.0f, 2.0f};
    int checked = 0;
    for (const float x : values)
        for (const float y : values)
            for (const float z : values) {
                const Vec3 d(x, y, z);
                if (d == Vec3(0.0f)) continue;
                const WatertightRay w(d);
                EXPECT_EQ(w.kz, max_axis(abs(d))) << d;  // the largest |component|, max_axis's ties
                EXPECT_EQ(w.kx, (w.kz + 1) % 3) << d;    // then the other two in cyclic order
                EXPECT_EQ(w.ky, (w.kz + 2) % 3) << d;
                EXPECT_EQ(w.sz, 1.0f / d[w.kz]) << d;
                EXPECT_EQ(w.sx, d[w.kx] * w.sz) << d;
                EXPECT_EQ(w.sy, d[w.ky] * w.sz) << d;
                ++checked;
            }
    EXPECT_EQ(checked, 7 * 7 * 7 - 1);
}

TEST(Triangle, SwappingTheShearAxesChangesNoBit) {
    // Woop et al. swap kx and ky when d[kz] < 0 to keep the winding; Glint does not, as the
    // swap only negates the edge functions, the determinant and the scaled t, exactly (each
    // edge function is a difference of two rounded products). So hits, t and barycentrics are
    // the same bits either way, and the SIMD and packet tests may order the axes as they like.
    std::mt19937 rng(29);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 v0 = glint_test::random_unit_vector(rng), v1 = glint_test::random_unit_vector(rng),
                   v2 = glint_test::random_unit_vector(rng);
        const Vec3 origin = glint_test::random_unit_vector(rng) * 3.0f;
        const Vec3 aim = (v0 + v1 + v2) / 3.0f + glint_test::random_unit_vector(rng) * 0.3f;
        const Ray ray(origin, normalize(aim - origin));
        const WatertightRay w(ray.direction);
        WatertightRay swapped = w;
        std::swap(swapped.kx, swapped.ky);
        std::swap(swapped.sx, swapped.sy);
        TriangleHit a{}, b{};
        const bool hit = intersect_triangle_watertight(ray, w, v0, v1, v2, a);
        ASSERT_EQ(hit, intersect_triangle_watertight(ray, swapped, v0, v1, v2, b)) << i;
        if (!hit) continue;
        ++hits;
        EXPECT_EQ(std::bit_cast<uint32_t>(a.t), std::bit_cast<uint32_t>(b.t)) << i;
        EXPECT_EQ(std::bit_cast<uint32_t>(a.v), std::bit_cast<uint32_t>(b.v)) << i;
        EXPECT_EQ(std::bit_cast<uint32_t>(a.w), std::bit_cast<uint32_t>(b.w)) << i;
    }
    EXPECT_GT(hits, 2000);  // not vacuous
}

TEST(Triangle, HitGivesTAndBarycentrics) {
    const Vec3 v0(0, 0, 0), v1(1, 0, 0), v2(0, 1, 0);
    TriangleHit th;
    ASSERT_TRUE(intersect_triangle(Ray({0.25f, 0.5f, 1}, {0, 0, -1}), v0, v1, v2, th));
    EXPECT_FLOAT_EQ(th.t, 1.0f);
    EXPECT_FLOAT_EQ(th.v, 0.25f);
    EXPECT_FLOAT_EQ(th.w, 0.5f);
    // Hits from the back too: culling is the shader's decision.
    ASSERT_TRUE(intersect_triangle(Ray({0.25f, 0.25f, -1}, {0, 0, 1}), v0, v1, v2, th));
}

TEST(Triangle, MissOutsideParallelAndTRange) {
    const Vec3 v0(0, 0, 0), v1(1, 0, 0), v2(0, 1, 0);
    TriangleHit th;
    EXPECT_FALSE(intersect_triangle(Ray({0.6f, 0.6f, 1}, {0, 0, -1}), v0, v1, v2, th));  // v + w > 1
    EXPECT_FALSE(intersect_triangle(Ray({-0.1f, 0.5f, 1}, {0, 0, -1}), v0, v1, v2, th));
    EXPECT_FALSE(intersect_triangle(Ray({0.2f, 0.2f, 1}, {1, 0, 0}), v0, v1, v2, th));  // parallel
    EXPECT_FALSE(intersect_triangle(Ray({0.2f, 0.2f, 1}, {0, 0, -1}, 0.0f, 0.5f), v0, v1, v2, th));
    EXPECT_FALSE(intersect_triangle(Ray({0.2f, 0.2f, 1}, {0, 0, 1}), v0, v1, v2, th));  // behind
}

TEST(Triangle, DegenerateNeverHits) {
    TriangleHit th;
    EXPECT_FALSE(intersect_triangle(Ray({0.5f, 0, 1}, {0, 0, -1}), {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, th));
}

// ---- Mesh -------------------------------------------------------------------------------

TEST(TriangleMesh, InterpolatesNormalsUvsAndMaterials) {
    MeshData d;
    d.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    d.indices = {0, 1, 2};
    d.normals = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    d.uvs = {{0, 0}, {1, 0}, {0, 1}};
    d.vertex_materials = {3, 4, 5};
    TriangleMesh mesh(d);
    mesh.prepare();
    Ray r({0.25f, 0.5f, 1}, {0, 0, -1});
    Hit h;
    ASSERT_TRUE(mesh.intersect(r, h));
    SurfaceInteraction si;
    mesh.interaction(r, h, si);
    EXPECT_NEAR(si.uv.x, 0.25f, 1e-6f);
    EXPECT_NEAR(si.uv.y, 0.5f, 1e-6f);
    EXPECT_NEAR(si.geometric_normal.z, 1.0f, 1e-6f);
    const Vec3 expected =
        normalize(Vec3(0, 0, 1) * 0.25f + normalize(Vec3(1, 0, 1)) * 0.25f + normalize(Vec3(0, 1, 1)) * 0.5f);
    EXPECT_NEAR(dot(si.shading_normal, expected), 1.0f, 1e-5f);
    ASSERT_TRUE(si.blends_materials);
    EXPECT_EQ(si.materials[1], 4u);
    EXPECT_NEAR(si.material_weights[0], 0.25f, 1e-6f);
    EXPECT_NEAR(si.material_weights[2], 0.5f, 1e-6f);
}

TEST(TriangleMesh, RejectsBadData) {
    MeshData out_of_range;
    out_of_range.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    out_of_range.indices = {0, 1, 3};
    EXPECT_THROW(TriangleMesh{out_of_range}, std::invalid_argument);
    MeshData nan_vertex = out_of_range;
    nan_vertex.indices = {0, 1, 2};
    nan_vertex.positions[1].x = std::nanf("");
    EXPECT_THROW(TriangleMesh{nan_vertex}, std::invalid_argument);
    EXPECT_THROW(TriangleMesh{MeshData{}}, std::invalid_argument);
}

TEST(TriangleMesh, SmoothNormalsAreAreaWeightedOverSharedVertices) {
    // A roof: two triangles sharing the ridge (vertices 0 and 1), tilted ±45° about x,
    // the second twice as large. Ridge normals lean towards the larger face; the eaves
    // keep their own face's normal.
    MeshData d;
    d.positions = {{0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {0, -1, -2}};
    d.indices = {0, 2, 1, 0, 1, 3};
    compute_smooth_normals(d);
    const Vec3 n_front = normalize(Vec3(0, 1, 1)), n_back = normalize(Vec3(0, 3, -3));
    const Vec3 ridge = normalize(cross(d.positions[2] - d.positions[0], d.positions[1] - d.positions[0]) +
                                 cross(d.positions[1] - d.positions[0], d.positions[3] - d.positions[0]));
    EXPECT_NEAR(dot(d.normals[0], ridge), 1.0f, 1e-6f);
    EXPECT_LT(ridge.z, 0.0f);  // the back face has twice the area
    EXPECT_NEAR(dot(d.normals[2], n_front), 1.0f, 1e-6f);
    EXPECT_NEAR(dot(d.normals[3], normalize(n_back)), 1.0f, 1e-6f);
}

// ---- Quad and box -----------------------------------------------------------------------

TEST(Quad, HitInsideMissOutside) {
    const Quad q({0, 0, 0}, {2, 0, 0}, {0, 0, -2});
    Ray r({0.5f, 3, -1.5f}, {0, -1, 0});
    Hit h;
    ASSERT_TRUE(q.intersect(r, h));
    EXPECT_FLOAT_EQ(h.t, 3.0f);
    SurfaceInteraction si;
    q.interaction(r, h, si);
    EXPECT_NEAR(si.uv.x, 0.25f, 1e-6f);
    EXPECT_NEAR(si.uv.y, 0.75f, 1e-6f);
    EXPECT_NEAR(si.geometric_normal.y, 1.0f, 1e-6f);  // (2,0,0) × (0,0,-2) = +y
    Ray outside({2.5f, 3, -1}, {0, -1, 0});
    EXPECT_FALSE(q.intersect(outside, h));
    Ray parallel({0.5f, 0, 1}, {0, 0, -1});
    EXPECT_FALSE(q.intersect(parallel, h));
}

TEST(Box, EntryFaceFromOutsideExitFaceFromInside) {
    const Box b({-1, -1, -1}, {1, 1, 1});
    Ray r({-5, 0.2f, 0.3f}, {1, 0, 0});
    Hit h;
    ASSERT_TRUE(b.intersect(r, h));
    EXPECT_FLOAT_EQ(h.t, 4.0f);
    SurfaceInteraction si;
    b.interaction(r, h, si);
    EXPECT_FLOAT_EQ(si.geometric_normal.x, -1.0f);
    EXPECT_TRUE(si.front_face);
    Ray inside({0, 0, 0}, {0, 0, 1});
    ASSERT_TRUE(b.intersect(inside, h));
    EXPECT_FLOAT_EQ(h.t, 1.0f);
    b.interaction(inside, h, si);
    EXPECT_FLOAT_EQ(si.geometric_normal.z, 1.0f);
    EXPECT_FALSE(si.front_face);
    Ray miss({-5, 2, 0}, {1, 0, 0});
    EXPECT_FALSE(b.intersect(miss, h));
}

// ---- Scene: transforms and instancing ---------------------------------------------------

TEST(Scene, TransformedInstancesShareOneShape) {
    Scene scene;
    const uint32_t m = scene.add_material(Material{});
    auto unit = std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f);
    scene.add_object(unit, m, Transform::translate({5, 0, 0}) * Transform::scale({2, 2, 2}));
    scene.add_object(unit, m, Transform::translate({-5, 0, 0}));
    const RenderScene prepared(std::move(scene));
    Ray r({5, 0, -10}, {0, 0, 1});
    Hit h;
    ASSERT_TRUE(prepared.intersect(r, h));
    EXPECT_NEAR(h.t, 8.0f, 1e-5f);  // radius 2 after scaling
    EXPECT_EQ(h.object, 0u);
    const SurfaceInteraction si = prepared.interaction(r, h);
    EXPECT_NEAR(si.p.z, -2.0f, 1e-5f);
    EXPECT_NEAR(si.geometric_normal.z, -1.0f, 1e-5f);
    Ray r2({-5, 0, -10}, {0, 0, 1});
    ASSERT_TRUE(prepared.intersect(r2, h));
    EXPECT_NEAR(h.t, 9.0f, 1e-5f);
    EXPECT_EQ(h.object, 1u);
    EXPECT_EQ(prepared.statistics().unique_shapes, 1u);
}

// Rays reach objects through the top rows of their inverse transform, which holds only
// for affine ones: a projective transform is refused where it is placed.
TEST(Scene, ProjectiveTransformsAreRefused) {
    Scene scene;
    const uint32_t m = scene.add_material(Material{});
    Matrix4 projective = Matrix4::identity();
    projective.m[3][2] = 0.25f;
    EXPECT_THROW(scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), m, Transform(projective)),
                 std::invalid_argument);
    EXPECT_TRUE(scene.objects().empty());
}

TEST(Scene, NonUniformScaleGivesEllipsoidNormals) {
    Scene scene;
    scene.add_material(Material{});
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), 0, Transform::scale({3, 1, 1}));
    const RenderScene prepared(std::move(scene));
    // Point on the ellipsoid x²/9 + y² = 1 at x = 3/√2·..., reached straight down from above.
    const float x = 1.5f, y = std::sqrt(1.0f - x * x / 9.0f);
    Ray r({x, 5, 0}, {0, -1, 0});
    Hit h;
    ASSERT_TRUE(prepared.intersect(r, h));
    EXPECT_NEAR(h.t, 5.0f - y, 1e-5f);
    const SurfaceInteraction si = prepared.interaction(r, h);
    const Vec3 expected = normalize(Vec3(x / 9.0f, y, 0));  // gradient of the implicit form
    EXPECT_NEAR(dot(si.geometric_normal, expected), 1.0f, 1e-5f);
}

TEST(Scene, EmptySceneHitsNothing) {
    Scene scene;
    const RenderScene prepared(std::move(scene));
    Ray r({0, 0, 0}, {0, 0, 1});
    Hit h;
    EXPECT_FALSE(prepared.intersect(r, h));
    EXPECT_FALSE(prepared.occluded(r));
}

TEST(Scene, DielectricShadowSetting) {
    for (auto mode : {DielectricShadows::None, DielectricShadows::Opaque}) {
        Scene scene;
        Material glass;
        glass.transparency = 1.0f;
        scene.dielectric_shadows = mode;
        scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), scene.add_material(glass));
        const RenderScene prepared(std::move(scene));
        const Ray shadow({0, 0, -5}, {0, 0, 1}, 0.0f, 10.0f);
        EXPECT_EQ(prepared.occluded(shadow), mode == DielectricShadows::Opaque);
        Ray camera = shadow;
        Hit h;
        EXPECT_TRUE(prepared.intersect(camera, h));  // still visible to camera rays
    }
}
