// Shadow rays from a packet's first hits toward delta lights, traced as packets before the
// hits are shaded (integrators/delta_light_shadows.h): each answer is the one
// RenderScene::occluded() gives the shadow ray Whitted's direct light casts there, and a light
// it did not trace gets no answer.

#include "glint/integrators/delta_light_shadows.h"
#include "glint/integrators/shading_point.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace glint {
namespace {

/// The shadow ray Whitted's direct light casts from `si` toward `ls` (light above the surface).
Ray whitted_shadow_ray(const SurfaceInteraction& si, const LightSample& ls) {
    const Vec3 ng = facing_geometric_normal(si);
    return shadow_ray(si.p, ng, ls, si.time);
}

/// `out`: where the ray straight down from `origin` first hits `scene` (a first hit of a
/// camera packet, as Li_given_first_hits() has it).
void first_hit_below(const RenderScene& scene, const Vec3& origin, SurfaceInteraction& out) {
    Ray ray(origin, Vec3(0, -1, 0));
    Hit hit;
    ASSERT_TRUE(scene.intersect(ray, hit));
    out = scene.interaction(ray, hit);
}

TEST(DeltaLightShadows, AnswerAsRenderSceneOccludedForEachLaneAndLight) {
    // Two point lights over a floor with a grid of spheres casting shadows on it.
    const RenderScene scene(load_toml_scene(glint_test::kScenesDir / "spheres.toml").scene);
    const std::vector<const Light*>& lights = scene.all_lights();
    ASSERT_GE(std::count_if(lights.begin(), lights.end(), [](const Light* l) { return l->is_delta(); }), 2);
    int blocked = 0, lit = 0;
    // Rows of eight rays straight down across the floor and the spheres; the last lane of
    // each packet is left out (a miss), to check it gets no answers.
    for (int row = 0; row < 24; ++row) {
        std::array<SurfaceInteraction, RayPacket::kSize> interactions;
        uint32_t hit_lanes = 0;
        for (uint32_t k = 0; k + 1 < RayPacket::kSize; ++k) {
            ASSERT_NO_FATAL_FAILURE(first_hit_below(
                scene, Vec3(-6.0f + 1.7f * float(k), 30.0f, -6.0f + 0.5f * float(row)), interactions[k]));
            hit_lanes |= 1u << k;
        }
        const std::array<DeltaLightShadows, RayPacket::kSize> shadows =
            trace_delta_light_shadows(scene, interactions, hit_lanes);
        for (uint32_t k = 0; k + 1 < RayPacket::kSize; ++k)
            for (uint32_t i = 0; i < lights.size(); ++i) {
                if (!lights[i]->is_delta()) continue;
                const SurfaceInteraction& si = interactions[k];
                const LightSample ls = lights[i]->sample(si.p, Vec2());
                const Ray shadow = whitted_shadow_ray(si, ls);
                const std::optional<bool> known = shadows[k].occluded(i);
                // A sphere's side turned from the light: see LeaveLightFromUnderTheSurface....
                if (dot(ls.direction, facing_geometric_normal(si)) < 0.0f) {
                    EXPECT_FALSE(known.has_value());
                    continue;
                }
                ASSERT_TRUE(known.has_value()) << "lane " << k << ", light " << i;
                EXPECT_EQ(*known, scene.occluded(shadow)) << "lane " << k << ", light " << i;
                ++(*known ? blocked : lit);
                EXPECT_FALSE(shadows[RayPacket::kSize - 1].occluded(i).has_value());
            }
    }
    // Both answers occur, so a cache that always said one of them would fail above.
    EXPECT_GT(blocked, 10);
    EXPECT_GT(lit, 10);
}

TEST(DeltaLightShadows, AnswerForTheWholeRayToTheLight) {
    // A blocker just under the point light, 90 % of the way up from the floor: only a ray
    // that reaches the light finds it (a table of shortened rays would call these points lit).
    const RenderScene scene(load_toml_scene_string(R"(
[[lights]]
type = "point"
position = [0, 10, 0]
intensity = 1

[[materials]]
name = "grey"
diffuse = 0.5

[[objects]]
type = "quad"
corner = [-5, 0, 5]
edge_u = [10, 0, 0]
edge_v = [0, 0, -10]
material = "grey"

[[objects]]
type = "mesh"
positions = [[0, 9, -1], [1, 9, -1], [1, 9, 1], [0, 9, 1]]
indices = [[0, 2, 1], [0, 3, 2]]
material = "grey"
)",
                                                   "blocker.toml", glint_test::kScenesDir)
                                .scene);
    int blocked = 0, lit = 0;
    for (int row = 0; row < 8; ++row) {
        std::array<SurfaceInteraction, RayPacket::kSize> interactions;
        // Floor points from x = -4 to 4: those with x > 0 lie in the blocker's shadow.
        for (uint32_t k = 0; k < RayPacket::kSize; ++k)
            ASSERT_NO_FATAL_FAILURE(first_hit_below(
                scene, Vec3(-3.9f + 1.1f * float(k), 5.0f, -2.0f + 0.5f * float(row)), interactions[k]));
        const std::array<DeltaLightShadows, RayPacket::kSize> shadows =
            trace_delta_light_shadows(scene, interactions, RayPacket::kAllLanes);
        for (uint32_t k = 0; k < RayPacket::kSize; ++k) {
            const SurfaceInteraction& si = interactions[k];
            const Ray shadow = whitted_shadow_ray(si, scene.all_lights()[0]->sample(si.p, Vec2()));
            const std::optional<bool> known = shadows[k].occluded(0);
            ASSERT_TRUE(known.has_value()) << "row " << row << ", lane " << k;
            EXPECT_EQ(*known, scene.occluded(shadow)) << "row " << row << ", lane " << k;
            EXPECT_EQ(*known, si.p.x > 0.0f) << "row " << row << ", lane " << k;
            ++(*known ? blocked : lit);
        }
    }
    EXPECT_GT(blocked, 10);
    EXPECT_GT(lit, 10);
}

TEST(DeltaLightShadows, LeaveLightFromUnderTheSurfaceToDirectLight) {
    // Seen from below, the floor's lights are on the other side: direct light casts those
    // shadow rays from under the surface with opaque dielectrics, so none is traced here.
    const RenderScene scene(load_toml_scene(glint_test::kScenesDir / "spheres.toml").scene);
    Ray ray(Vec3(-5.5f, -10.0f, -5.5f), Vec3(0, 1, 0));
    Hit hit;
    ASSERT_TRUE(scene.intersect(ray, hit));
    std::array<SurfaceInteraction, RayPacket::kSize> interactions;
    interactions[0] = scene.interaction(ray, hit);
    const std::array<DeltaLightShadows, RayPacket::kSize> shadows = trace_delta_light_shadows(scene, interactions, 1u);
    const SurfaceInteraction& si = interactions[0];
    for (uint32_t i = 0; i < scene.all_lights().size(); ++i) {
        if (!scene.all_lights()[i]->is_delta()) continue;
        const LightSample ls = scene.all_lights()[i]->sample(si.p, Vec2());
        const Vec3 ng = facing_geometric_normal(si);
        ASSERT_LT(dot(ls.direction, ng), 0.0f);
        EXPECT_FALSE(shadows[0].occluded(i).has_value());
    }
}

TEST(DeltaLightShadows, AreTracedWherePacketsPay) {
    // Spheres and quads take packets lane by lane: the render traces their shadow rays one by
    // one. A mesh traces them together.
    EXPECT_FALSE(RenderScene(load_toml_scene(glint_test::kScenesDir / "spheres.toml").scene).packets_pay());
    EXPECT_FALSE(RenderScene(load_toml_scene(glint_test::kScenesDir / "cornell.toml").scene).packets_pay());
    EXPECT_TRUE(RenderScene(load_toml_scene(glint_test::kScenesDir / "bunny_glass.toml").scene).packets_pay());
}

}  // namespace
}  // namespace glint
