// glTF's metallicRoughnessTexture (glTF 2.0, §3.9.2): its green channel times roughnessFactor
// is the roughness and its blue channel times metallicFactor the metalness at each hit, read
// as linear data, and kd, ka and F0 follow from them as from the factors (docs/assets.md).
// Checked through material_at_hit, the function both integrators build their Bsdf from, and
// by rendering.

#include "gltf_texture_files.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/image/film.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/materials/bsdf.h"
#include "glint/materials/material_at_hit.h"
#include "glint/math/color.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using glint::Color;
using glint::Vec2;
using nlohmann::json;

using glint_test::quad_json_with;
using glint_test::Texel;
using glint_test::write_png;

/// Texture coordinates of the centres of the left and right texel of a 2×1 texture, and of
/// the one texel of a 1×1 texture: bilinear lookups there return the texel unblended.
const Vec2 kLeft(0.25f, 0.5f), kRight(0.75f, 0.5f), kCentre(0.5f, 0.5f);

/// An 8-bit texel value read as data.
float data(unsigned char v) { return float(v) / 255.0f; }

/// A metallic-roughness material on texture 0 with these factors.
json textured(float metallic, float roughness, const json& base = {0.8, 0.6, 0.4, 1.0}) {
    return {{"name", "textured"},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", base},
              {"metallicFactor", metallic},
              {"roughnessFactor", roughness},
              {"metallicRoughnessTexture", {{"index", 0}}}}}};
}

/// Load the quad with `material` and the metallic-roughness texture `texels` as texture 0.
glint::GltfScene load_with_texture(const json& material, const std::vector<Texel>& texels) {
    const auto dir = glint_test::temp_dir();
    write_png(dir / "mr.png", texels);
    return glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", quad_json_with(material, {"mr.png"})));
}

const glint::Material& only_material(const glint::GltfScene& s) { return s.loaded.scene.materials()[0]; }

/// F0 and diffuse of glTF's metallic-roughness model for a base colour and metalness.
Color f0(const Color& base, float metallic) { return glint::lerp(metallic, Color(0.04f), base); }
Color diffuse(const Color& base, float metallic) { return base * (1.0f - metallic); }

void expect_color_near(const Color& a, const Color& b, const char* what) {
    EXPECT_NEAR(a.r, b.r, 1e-6f) << what;
    EXPECT_NEAR(a.g, b.g, 1e-6f) << what;
    EXPECT_NEAR(a.b, b.b, 1e-6f) << what;
}

}  // namespace

TEST(GltfMetallicRoughness, EachHalfOfTheTextureGivesItsRoughnessF0AndDiffuse) {
    // Left: roughness 0 and metal (G = 0, B = 1); right: roughness 1 and dielectric (G = 1,
    // B = 0). Red holds what a packed occlusion map would put there; it must not matter.
    const auto s = load_with_texture(textured(1.0f, 1.0f), {{255, 0, 255}, {0, 255, 0}});
    EXPECT_TRUE(s.report.ignored.empty()) << s.report.ignored.front();
    const glint::Material& m = only_material(s);
    const Color base(0.8f, 0.6f, 0.4f);

    const glint::MaterialAtHit metal = glint::material_at_hit(m, kLeft, {});
    EXPECT_EQ(metal.roughness, 0.0f);
    EXPECT_EQ(metal.reflectivity, base) << "F0 of metal is the base colour";
    EXPECT_EQ(metal.diffuse, Color(0.0f)) << "metal has no diffuse part";
    EXPECT_EQ(metal.ambient, metal.diffuse);

    const glint::MaterialAtHit plastic = glint::material_at_hit(m, kRight, {});
    EXPECT_EQ(plastic.roughness, 1.0f);
    EXPECT_EQ(plastic.reflectivity, Color(0.04f)) << "F0 of the dielectric part is 4%";
    EXPECT_EQ(plastic.diffuse, base);
    EXPECT_EQ(plastic.ambient, plastic.diffuse);

    // The Bsdf built from them: the smooth half is the exact (delta) Fresnel mirror, the rough
    // half a GGX lobe beside the diffuse one.
    const glint::Vec3 up(0, 0, 1), wo = glint::normalize(glint::Vec3(0.3f, 0, 1));
    const glint::Bsdf smooth(m, metal, up, up, wo, {});
    EXPECT_FALSE(smooth.has_glossy_lobes());
    EXPECT_FALSE(smooth.specular().reflection.is_black());
    const glint::Bsdf rough(m, plastic, up, up, wo, {});
    EXPECT_TRUE(rough.has_glossy_lobes());
    EXPECT_TRUE(rough.specular().reflection.is_black());
}

TEST(GltfMetallicRoughness, GreenIsRoughnessAndBlueIsMetalness) {
    // Three different channel values: reading red, or swapping green and blue, gives another
    // roughness and F0.
    const unsigned char r = 255, g = 51, b = 204;
    const auto s = load_with_texture(textured(1.0f, 1.0f), {{r, g, b}});
    const glint::MaterialAtHit at = glint::material_at_hit(only_material(s), kCentre, {});
    const Color base(0.8f, 0.6f, 0.4f);
    EXPECT_NEAR(at.roughness, data(g), 1e-6f);
    expect_color_near(at.reflectivity, f0(base, data(b)), "F0 = mix(0.04, base, B)");
    expect_color_near(at.diffuse, diffuse(base, data(b)), "kd = base·(1 − B)");
}

TEST(GltfMetallicRoughness, TextureValuesAreLinearNotSrgbDecoded) {
    // 128 is 0.502 as data; an sRGB decode would make it 0.216.
    const auto s = load_with_texture(textured(1.0f, 1.0f), {{128, 128, 128}});
    const glint::MaterialAtHit at = glint::material_at_hit(only_material(s), kCentre, {});
    EXPECT_NEAR(at.roughness, data(128), 1e-6f);
    expect_color_near(at.reflectivity, f0(Color(0.8f, 0.6f, 0.4f), data(128)), "metalness 0.502");
}

TEST(GltfMetallicRoughness, FactorsMultiplyTheTexture) {
    const float metallic_factor = 0.25f, roughness_factor = 0.5f;
    const auto s = load_with_texture(textured(metallic_factor, roughness_factor), {{0, 128, 128}});
    const glint::MaterialAtHit at = glint::material_at_hit(only_material(s), kCentre, {});
    const Color base(0.8f, 0.6f, 0.4f);
    EXPECT_NEAR(at.roughness, roughness_factor * data(128), 1e-6f);
    expect_color_near(at.reflectivity, f0(base, metallic_factor * data(128)), "F0 with metalness factor × B");
    expect_color_near(at.diffuse, diffuse(base, metallic_factor * data(128)), "kd with metalness factor × B");
}

TEST(GltfMetallicRoughness, BaseColourTextureTintsF0AndDiffuse) {
    // glTF's base colour is factor × texture (sRGB), in F0 as in kd.
    const auto dir = glint_test::temp_dir();
    write_png(dir / "mr.png", {{0, 255, 128}});
    write_png(dir / "base.png", {{255, 128, 0}});
    json material = textured(1.0f, 1.0f, {0.5, 1.0, 1.0, 1.0});
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 1}};
    const auto s =
        glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", quad_json_with(material, {"mr.png", "base.png"})));
    const glint::MaterialAtHit at = glint::material_at_hit(only_material(s), kCentre, {});
    const Color base(0.5f * 1.0f, glint::srgb_to_linear(data(128)), 0.0f);
    expect_color_near(at.reflectivity, f0(base, data(128)), "F0 = mix(0.04, factor × texture, metalness)");
    expect_color_near(at.diffuse, diffuse(base, data(128)), "kd = factor × texture × (1 − metalness)");
    EXPECT_EQ(at.roughness, 1.0f);
}

TEST(GltfMetallicRoughness, OneImageAsBaseColourAndMetallicRoughnessIsDecodedBothWays) {
    // The same texture in both slots: sRGB-decoded as colour, read as it is as data.
    const auto dir = glint_test::temp_dir();
    write_png(dir / "both.png", {{128, 128, 128}});
    json material = textured(1.0f, 1.0f, {1.0, 1.0, 1.0, 1.0});
    material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const auto s = glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", quad_json_with(material, {"both.png"})));
    EXPECT_EQ(s.report.textures, 2u) << "one scene texture per decoding";
    const glint::MaterialAtHit at = glint::material_at_hit(only_material(s), kCentre, {});
    EXPECT_NEAR(at.roughness, data(128), 1e-6f);
    expect_color_near(at.diffuse, diffuse(Color(glint::srgb_to_linear(data(128))), data(128)),
                      "sRGB base, linear metalness");
}

TEST(GltfMetallicRoughness, TextureInsideAGlbIsReadAsData) {
    // The image in the binary chunk (a bufferView), as exporters write GLB files.
    const auto dir = glint_test::temp_dir();
    const std::string png = write_png(dir / "mr.png", {{0, 128, 64}});
    json j = quad_json_with(textured(1.0f, 1.0f), {});
    const std::string quad = glint_test::quad_buffer();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", quad.size()}, {"byteLength", png.size()}});
    j["buffers"][0]["byteLength"] = quad.size() + png.size();
    j["images"] = json::array({{{"bufferView", 2}, {"mimeType", "image/png"}}});
    j["textures"] = json::array({{{"source", 0}}});
    glint_test::write_file(dir / "quad.glb", glint_test::make_glb(j, quad + png));
    const auto s = glint::load_gltf_scene(dir / "quad.glb");
    const glint::MaterialAtHit at = glint::material_at_hit(only_material(s), kCentre, {});
    EXPECT_NEAR(at.roughness, data(128), 1e-6f);
    expect_color_near(at.reflectivity, f0(Color(0.8f, 0.6f, 0.4f), data(64)), "metalness 64/255 from the blue channel");
}

TEST(GltfMetallicRoughness, TransmissionRoughnessFollowsTheTexture) {
    // KHR_materials_transmission's lobe shares the specular roughness: glass where the texture
    // says 0 refracts exactly, frosted where it says 1.
    json material = textured(0.0f, 1.0f);
    material["extensions"] = {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}};
    const auto s = load_with_texture(material, {{0, 0, 0}, {0, 255, 0}});
    const glint::Material& m = only_material(s);
    const glint::Vec3 up(0, 0, 1), wo = glint::normalize(glint::Vec3(0.3f, 0, 1));
    const glint::Bsdf clear(m, glint::material_at_hit(m, kLeft, {}), up, up, wo, {1.0f, m.ior});
    EXPECT_FALSE(clear.has_glossy_lobes());
    EXPECT_TRUE(clear.specular().refracted);
    const glint::Bsdf frosted(m, glint::material_at_hit(m, kRight, {}), up, up, wo, {1.0f, m.ior});
    EXPECT_TRUE(frosted.has_glossy_lobes());
    EXPECT_FALSE(frosted.specular().refracted);
}

TEST(GltfMetallicRoughness, TextureRoughnessZeroRendersAsRoughnessFactorZero) {
    // The quad under glTF's default lighting. Where the texture says roughness 0 and
    // metalness 0, factors 1 and 1 must give the very bits of factors 0 and 0 without a
    // texture (the exact 4% mirror beside the diffuse base), with both integrators; a texture
    // that says roughness 1 must not (so the comparison can fail).
    const auto dir = glint_test::temp_dir();
    write_png(dir / "smooth.png", {{0, 0, 0}});
    write_png(dir / "rough.png", {{0, 255, 0}});
    const json untextured = {
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.8, 0.6, 0.4, 1.0}}, {"metallicFactor", 0}, {"roughnessFactor", 0}}}};
    auto film_of = [&](const json& material, const std::string& image, const std::string& integrator) {
        glint::GltfScene s =
            glint::load_gltf_scene(glint_test::write_gltf(dir, image, quad_json_with(material, {image + ".png"})));
        glint::RenderSettings settings = s.loaded.settings;
        settings.width = 32;
        settings.height = 24;
        settings.integrator = integrator;
        const glint::RenderScene scene(std::move(s.loaded.scene));
        glint::Film film(settings.width, settings.height);
        glint::make_integrator(settings)->render(scene, settings, film);
        return film;
    };
    auto identical = [](const glint::Film& a, const glint::Film& b) {
        for (uint32_t y = 0; y < a.height(); ++y)
            for (uint32_t x = 0; x < a.width(); ++x)
                if (!(a.at(x, y) == b.at(x, y))) return false;
        return true;
    };
    for (const char* integrator : {"whitted", "path"}) {
        const glint::Film plain = film_of(untextured, "smooth", integrator);
        EXPECT_TRUE(identical(plain, film_of(textured(1.0f, 1.0f), "smooth", integrator))) << integrator;
        EXPECT_FALSE(identical(plain, film_of(textured(1.0f, 1.0f), "rough", integrator))) << integrator;
    }
}
