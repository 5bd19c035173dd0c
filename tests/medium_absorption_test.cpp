// Beer-Lambert absorption inside dielectrics (Material::absorption; TOML absorption and
// attenuation_color; glTF KHR_materials_volume) and the dielectric F0 of KHR_materials_ior
// and KHR_materials_specular, against closed forms along single rays.

#include "gltf_test_files.h"
#include "toml_text.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/geometry/box.h"
#include "glint/integrators/path_integrator.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace glint;
using nlohmann::json;

namespace {

constexpr float kF = 0.04f;  // Schlick's F head-on for index 1.5 in air

Color whitted(const RenderScene& scene, const Ray& ray, uint32_t max_depth) {
    Sampler sampler(0, 1);
    sampler.start_pixel_sample(0, 0);
    TraceContext context{sampler};
    return WhittedIntegrator(max_depth).Li(scene, ray, context);
}

/// A glass slab of `thickness` (y from -thickness to 0) under a white sky, seen from above.
RenderScene slab(float thickness, const Color& absorption) {
    Scene scene;
    scene.background = Background::constant(Color(1.0f));
    Material glass;
    glass.diffuse = Color(0.0f);
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    glass.absorption = absorption;
    scene.add_object(std::make_shared<Box>(Vec3(-50, -thickness, -50), Vec3(50, 0, 50)), scene.add_material(glass));
    return RenderScene(std::move(scene));
}

const Ray kStraightDown(Vec3(0, 5, 0), Vec3(0, -1, 0));

}  // namespace

TEST(MediumAbsorption, ThickGlassTintsMoreThanThin) {
    // Depth 2: the front face's reflection F, and (1 − F)² through both faces with T = e^(−σd).
    const Color sigma(std::log(2.0f), 0.0f, std::log(4.0f));  // per unit: keeps 1/2, 1, 1/4
    for (const float d : {1.0f, 2.0f}) {
        const Color got = whitted(slab(d, sigma), kStraightDown, 2);
        const Color expected(kF + (1 - kF) * (1 - kF) * std::pow(0.5f, d), kF + (1 - kF) * (1 - kF),
                             kF + (1 - kF) * (1 - kF) * std::pow(0.25f, d));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-5f) << "thickness " << d << " channel " << c;
    }
}

TEST(MediumAbsorption, PathTracerAttenuatesTheSameWay) {
    // Head-on through a clear slab the path tracer's expected value is the Whitted series'
    // (every lobe is a delta): the ratio of absorbing to clear estimates is T = e^(−σd).
    const PathIntegrator path(2);
    auto mean = [&](const RenderScene& scene) {
        Color sum;
        constexpr int kSamples = 20000;
        Sampler sampler(7, 1);
        for (int i = 0; i < kSamples; ++i) {
            sampler.start_pixel_sample(0, uint32_t(i));
            TraceContext context{sampler};
            sum += path.Li(scene, kStraightDown, context);
        }
        return sum / float(kSamples);
    };
    const Color clear = mean(slab(1.0f, Color(0.0f)));
    const Color tinted = mean(slab(1.0f, Color(std::log(2.0f), 0.0f, 0.0f)));
    // Only the (1 − F)² share is absorbed: R = F + (1 − F)²/2 of the clear F + (1 − F)².
    EXPECT_NEAR(tinted.r / clear.r, (kF + (1 - kF) * (1 - kF) * 0.5f) / (kF + (1 - kF) * (1 - kF)), 0.02f);
    EXPECT_NEAR(tinted.g / clear.g, 1.0f, 1e-6f);
}

TEST(MediumAbsorption, TomlAttenuationColorIsWhatIsLeftAfterTheDistance) {
    const auto material = [](const std::string& keys) {
        return load("[[materials]]\nname = \"glass\"\ntransparency = 1\n" + keys).scene.material(0);
    };
    const Material m = material("attenuation_color = [0.5, 1, 0.25]\nattenuation_distance = 2\n");
    EXPECT_NEAR(m.absorption.r, std::log(2.0f) / 2.0f, 1e-6f);
    EXPECT_EQ(m.absorption.g, 0.0f);
    EXPECT_NEAR(m.absorption.b, std::log(4.0f) / 2.0f, 1e-6f);
    EXPECT_EQ(material("absorption = [0.1, 0.2, 0.3]\n").absorption, Color(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(material("").absorption, Color(0.0f));
}

TEST(MediumAbsorption, TomlMistakes) {
    expect_error("[[materials]]\nname = \"g\"\nabsorption = 1\nattenuation_color = 0.5\n", "test.toml:4:21:",
                 {"materials[0].attenuation_color", "either absorption or attenuation_color"});
    expect_error("[[materials]]\nname = \"g\"\nattenuation_color = [0, 1, 1]\n", "test.toml:3:21:",
                 {"components in (0, 1]"});
    expect_error("[[materials]]\nname = \"g\"\nattenuation_distance = 2\n", "test.toml:3:24:",
                 {"attenuation_color beside it"});
    expect_error("[[materials]]\nname = \"g\"\nattenuation_color = 0.5\nattenuation_distance = 0\n",
                 "test.toml:4:24:", {"a positive distance"});
}

namespace {

/// The quad and a copy of it `gap` below (two nodes of one mesh), both with `material`,
/// under the default lighting's grey sky: a slab of that thickness for a transmissive one.
GltfScene two_quads(const json& material, float gap) {
    json j = glint_test::quad_json("quad.bin");
    j["materials"][0] = material;
    j["materials"][0]["doubleSided"] = true;
    j["nodes"] = json::array({{{"name", "top"}, {"mesh", 0}},
                              {{"name", "bottom"}, {"mesh", 0}, {"translation", {0.0f, -gap, 0.0f}}}});
    j["scenes"][0]["nodes"] = json::array({0, 1});
    return load_gltf_scene(glint_test::write_gltf(glint_test::temp_dir(), "quads", j));
}

json glass(const json& extensions) {
    json m = {{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0}}},
              {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}};
    for (const auto& [name, value] : extensions.items()) m["extensions"][name] = value;
    return m;
}

}  // namespace

TEST(GltfVolume, AttenuatesWhatCrossesTheSlabByBeerLambert) {
    const json volume = {{"KHR_materials_volume", {{"attenuationColor", {0.5, 1, 1}}, {"attenuationDistance", 1}}}};
    GltfScene with = two_quads(glass(volume), 2.0f);
    GltfScene without = two_quads(glass(json::object()), 2.0f);
    EXPECT_NEAR(with.loaded.scene.material(0).absorption.r, std::log(2.0f), 1e-6f);
    const RenderScene tinted(std::move(with.loaded.scene)), clear(std::move(without.loaded.scene));
    const Color a = whitted(tinted, kStraightDown, 2), b = whitted(clear, kStraightDown, 2);
    // Over 2 units half is kept per unit: the through share (1 − F)² drops to a quarter.
    const float sky = b.g / (kF + (1 - kF) * (1 - kF));
    EXPECT_NEAR(a.r, sky * (kF + (1 - kF) * (1 - kF) * 0.25f), 1e-5f);
    EXPECT_NEAR(a.g, b.g, 1e-6f);
}

TEST(GltfSpecular, ScalesAndTintsTheDielectricReflection) {
    // A black, smooth, non-metal quad reflects the sky by its F0 head-on: 4 % without the
    // extension, specularFactor × specularColorFactor × 4 % with it.
    auto reflected = [](const json& extensions) {
        json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0},
                                            {"roughnessFactor", 0}}}};
        if (!extensions.empty()) m["extensions"] = extensions;
        GltfScene s = two_quads(m, 2.0f);
        const RenderScene scene(std::move(s.loaded.scene));
        return whitted(scene, kStraightDown, 1);
    };
    const Color plain = reflected(json::object());
    const Color tinted =
        reflected({{"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {1, 0.5, 0.25}}}}});
    EXPECT_GT(plain.g, 0.0f);
    EXPECT_NEAR(tinted.r, plain.r * 0.5f, 1e-6f);
    EXPECT_NEAR(tinted.g, plain.g * 0.25f, 1e-6f);
    EXPECT_NEAR(tinted.b, plain.b * 0.125f, 1e-6f);
    // KHR_materials_ior moves F0 to ((n − 1)/(n + 1))²: 1/9 for n = 2.
    const Color dense = reflected({{"KHR_materials_ior", {{"ior", 2.0}}}});
    EXPECT_NEAR(dense.g / plain.g, (1.0f / 9.0f) / 0.04f, 1e-4f);
}
