// Light units (docs/units.md): glTF photometric quantities become Glint's π-scaled ones,
// E_glint = E_physical / π, and a white Lambertian surface reflects L = E_glint·cosθ.

#include "gltf_test_files.h"

#include "glint/image/film.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/assets/gltf_scene_loader.h"
#include "glint/lights/light.h"
#include "glint/math/constants.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using nlohmann::json;

/// The quad lit by one KHR_lights_punctual light on a node at `position` turned by `rotation`.
glint::GltfScene quad_with_light(const json& light, const std::vector<float>& position,
                                 const std::vector<float>& rotation = {0, 0, 0, 1}) {
    json j = glint_test::quad_json("quad.bin");
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    j["extensions"]["KHR_lights_punctual"]["lights"] = json::array({light});
    j["nodes"].push_back({{"name", "lamp"}, {"translation", position}, {"rotation", rotation},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    j["scenes"][0]["nodes"].push_back(1);
    return glint::load_gltf_scene(glint_test::write_gltf(glint_test::temp_dir(), "quad", j));
}

// Pointing straight down: -z of the node turned -90° about x.
const std::vector<float> kDown = {-0.70710678f, 0.0f, 0.0f, 0.70710678f};

TEST(LightUnits, PointLightOfICandelaAtDistanceDGivesIOverPiDSquared) {
    const float intensity = 100.0f, d = 4.0f;
    glint::GltfScene s = quad_with_light({{"type", "point"}, {"intensity", intensity}}, {0, d, 0});
    ASSERT_EQ(s.loaded.scene.lights().size(), 1u);
    const auto& light = dynamic_cast<const glint::PointLight&>(*s.loaded.scene.lights()[0]);
    EXPECT_EQ(light.falloff(), glint::Falloff::InverseSquare);
    EXPECT_NEAR(light.intensity().r, intensity / glint::kPi, 1e-4f);
    const glint::LightSample ls = light.sample(glint::Vec3(0.0f), {});
    EXPECT_NEAR(ls.radiance.g / glint::kPi, intensity / (glint::kPi * d * d), 1e-5f);
    EXPECT_NEAR(ls.distance, d, 1e-6f);
    EXPECT_NEAR(ls.direction.y, 1.0f, 1e-6f);
}

TEST(LightUnits, ColouredPointLightScalesEachChannel) {
    glint::GltfScene s = quad_with_light({{"type", "point"}, {"intensity", 10.0f}, {"color", {1.0, 0.5, 0.25}}}, {0, 1, 0});
    const glint::LightSample ls = s.loaded.scene.lights()[0]->sample(glint::Vec3(0.0f), {});
    EXPECT_NEAR(ls.radiance.r / glint::kPi, 10.0f / glint::kPi, 1e-5f);
    EXPECT_NEAR(ls.radiance.g / glint::kPi, 5.0f / glint::kPi, 1e-5f);
    EXPECT_NEAR(ls.radiance.b / glint::kPi, 2.5f / glint::kPi, 1e-5f);
}

TEST(LightUnits, DirectionalLightOfELuxGivesEOverPi) {
    glint::GltfScene s = quad_with_light({{"type", "directional"}, {"intensity", 3.0f}}, {0, 5, 0}, kDown);
    const glint::LightSample ls = s.loaded.scene.lights()[0]->sample(glint::Vec3(7.0f, 0.0f, -3.0f), {});
    EXPECT_NEAR(ls.radiance.r / glint::kPi, 3.0f / glint::kPi, 1e-5f);
    EXPECT_NEAR(ls.direction.y, 1.0f, 1e-5f) << "the light travels along the node's -z (down here)";
    EXPECT_TRUE(std::isinf(ls.distance));
}

TEST(LightUnits, SpotLightOnAxisIsAPointLightAndDarkOutsideItsCone) {
    const float intensity = 50.0f, d = 2.0f;
    glint::GltfScene s = quad_with_light(
        {{"type", "spot"}, {"intensity", intensity}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}},
        {0, d, 0}, kDown);
    const auto& light = *s.loaded.scene.lights()[0];
    EXPECT_NEAR(light.sample(glint::Vec3(0.0f), {}).radiance.r / glint::kPi, intensity / (glint::kPi * d * d), 1e-5f);
    EXPECT_EQ(light.sample(glint::Vec3(5.0f, 0.0f, 0.0f), {}).radiance.r, 0.0f);  // 68° off axis
}

TEST(LightUnits, RenderedWhiteLambertianShowsTheDocumentedRadiance) {
    // Camera straight above the light's foot: the centre pixel sees L = f·E·cosθ with E = I/d².
    // The quad's glTF material (metallic 0, roughness 1, white) is a white Lambertian plus
    // glTF's 4% specular, a GGX lobe of alpha 1: at normal incidence G = 1, F = F0 = 0.04 and
    // D = 1/π, so f = 1/π + 0.04/(4π) and L = 1.01·I/(π d²).
    const float intensity = 20.0f, d = 2.0f;
    json j = glint_test::quad_json("quad.bin");
    j["extensions"]["KHR_lights_punctual"]["lights"] = json::array({{{"type", "point"}, {"intensity", intensity}}});
    j["nodes"].push_back({{"translation", {0, d, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.1}, {"znear", 0.1}}}}});
    j["nodes"].push_back({{"camera", 0}, {"translation", {0, 5, 0.001}}, {"rotation", kDown}});
    j["scenes"][0]["nodes"] = {0, 1, 2};
    glint::GltfScene s = glint::load_gltf_scene(glint_test::write_gltf(glint_test::temp_dir(), "quad", j));
    glint::Scene& scene = s.loaded.scene;
    const glint::RenderScene prepared(std::move(scene));
    glint::RenderSettings settings;
    settings.width = settings.height = 3;
    glint::Film film(3, 3);
    glint::WhittedIntegrator(1).render(prepared, settings, film, {});
    EXPECT_NEAR(film.at(1, 1).r, 1.01f * intensity / (glint::kPi * d * d), 2e-3f);
    EXPECT_EQ(prepared.ambient_light(), glint::Color(0.0f)) << "files with lights get no ambient term";
}

}  // namespace
