// The viewer's heatmaps (glint/integrators/cost_map.h) on one triangle seen from straight
// above: each count follows from the structure. The camera ray of a pixel inside the
// triangle, or inside its box but outside it, visits the top level's one node and the
// mesh's one wide node and tests the one triangle; a ray outside the box visits nothing.
#include "glint/integrators/cost_map.h"

#include "glint/geometry/triangle_mesh.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/lights/light.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

namespace {

using namespace glint;

/// Triangle (-1,-1), (1,-1), (-1,1) in the plane z = 0, seen by an orthographic camera from
/// +z over [-2, 2]², 8×8 pixels of half a unit: pixel (2, 5) lies inside the triangle,
/// (5, 2) inside its box but beyond its long edge, (0, 0) outside the box.
RenderScene one_triangle(float reflectivity, bool light) {
    Scene scene;
    MeshData data;
    data.positions = {{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}};
    data.indices = {0, 1, 2};
    Material m;
    m.reflectivity = Color(reflectivity);
    scene.add_object(std::make_shared<TriangleMesh>(data, "triangle"), scene.add_material(m));
    if (light) scene.add_light(std::make_unique<PointLight>(Vec3(0, 0, 3), Color(1.0f), Falloff::None));
    scene.camera = Camera::orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 4.0f);
    return RenderScene(std::move(scene));
}

RenderSettings eight_by_eight() {
    RenderSettings s;
    s.width = 8;
    s.height = 8;
    s.max_depth = 3;
    return s;
}

}  // namespace

TEST(CostMap, CountsOnOneTriangleAreExact) {
    const RenderScene scene = one_triangle(0.0f, true);
    const RenderSettings s = eight_by_eight();
    const auto integrator = make_integrator(s);
    const CostMap map = compute_cost_map(scene, *integrator, s, scene.camera());
    ASSERT_EQ(map.pixels.size(), 64u);
    const PixelCost inside = map.at(2, 5), in_box = map.at(5, 2), outside = map.at(0, 0);
    EXPECT_EQ(inside.nodes, 2u);
    EXPECT_EQ(inside.primitives, 1u);
    EXPECT_EQ(inside.shadow_rays, 1u) << "one light";
    EXPECT_EQ(inside.depth, 0u);
    EXPECT_EQ(in_box.nodes, 2u);
    EXPECT_EQ(in_box.primitives, 1u);
    EXPECT_EQ(in_box.shadow_rays, 0u) << "a ray that misses casts no shadow ray";
    EXPECT_EQ(outside.nodes, 0u);
    EXPECT_EQ(outside.primitives, 0u);
    EXPECT_EQ(map.max(CostKind::ShadowRays), 1u);
}

TEST(CostMap, AMirrorAddsItsReflectionToTheDepth) {
    const RenderScene scene = one_triangle(0.5f, false);
    const RenderSettings s = eight_by_eight();
    const auto integrator = make_integrator(s);
    const CostMap map = compute_cost_map(scene, *integrator, s, scene.camera());
    // The reflection leaves the triangle upwards: it starts above the flat box and meets nothing.
    EXPECT_EQ(map.at(2, 5).depth, 1u);
    EXPECT_EQ(map.at(2, 5).nodes, 2u);
    EXPECT_EQ(map.at(2, 5).shadow_rays, 0u);
    EXPECT_EQ(map.at(5, 2).depth, 0u);
    EXPECT_EQ(cost_kind_name(CostKind::Nodes), "BVH nodes visited");
}

TEST(CostMap, CountingTraversalsFindTheSameHits) {
    const RenderScene scene = one_triangle(0.5f, true);
    for (int i = 0; i < 64; ++i) {
        const Ray ray = scene.camera().generate_ray(0.25f + 0.125f * float(i), 0.3f + 0.12f * float(i), 8, 8);
        Ray plain = ray, counted = ray;
        Hit a, b;
        TraversalStats stats;
        EXPECT_EQ(scene.intersect(plain, a), scene.intersect_counted(counted, b, stats)) << i;
        EXPECT_EQ(a.object, b.object);
        EXPECT_EQ(plain.tmax, counted.tmax);
        EXPECT_EQ(scene.occluded(ray), scene.occluded_counted(ray, scene.dielectric_shadows(), stats));
    }
}
