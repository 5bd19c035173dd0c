// glTF KHR_texture_transform (the extension's README): each textureInfo that carries it is
// looked up at T·R·S·(u, v, 1), through a UvTransformTexture the scene owns. A 4×1 texture
// of four distinct colours shows which texel a lookup at a texel centre lands on, with and
// without the extension.

#include "gltf_texture_files.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/diagnostics.h"
#include "glint/image/film.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/materials/material_at_hit.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace {

using glint::Color;
using glint::Vec2;
using nlohmann::json;

/// Texels 0..3 of the test texture, left to right, as 8-bit data.
const std::vector<glint_test::Texel> kTexels = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};

/// Texel i of the texture as data (the metallic-roughness slot reads it undecoded).
Color texel(int i) {
    const auto& t = kTexels[std::size_t(i)];
    return {t[0] / 255.0f, t[1] / 255.0f, t[2] / 255.0f};
}

/// The centre of texel i: a bilinear lookup there returns the texel unblended.
Vec2 centre(int i) { return {(float(i) + 0.5f) / 4.0f, 0.5f}; }

/// A textureInfo of texture 0, with `transform` as its KHR_texture_transform unless null.
json info(const json& transform = nullptr) {
    json j = {{"index", 0}};
    if (!transform.is_null()) j["extensions"] = {{"KHR_texture_transform", transform}};
    return j;
}

/// Load the quad with `material` on the 4×1 texture, KHR_texture_transform declared used.
glint::GltfScene load_with_material(const json& material) {
    const auto dir = glint_test::temp_dir();
    glint_test::write_png(dir / "four.png", kTexels);
    json j = glint_test::quad_json_with(material, {"four.png"});
    j["extensionsUsed"] = {"KHR_texture_transform"};
    return glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", j));
}

/// A white dielectric whose base colour is texture 0 seen through `transform`.
glint::GltfScene base_colour(const json& transform) {
    return load_with_material(
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}, {"baseColorTexture", info(transform)}}}});
}

/// The diffuse colour at uv of the only material, undecoded from sRGB back to 8-bit data.
Color seen(const glint::GltfScene& s, Vec2 uv) {
    const Color c = glint::material_at_hit(s.loaded.scene.materials()[0], uv, {}).diffuse;
    return {glint::linear_to_srgb(c.r), glint::linear_to_srgb(c.g), glint::linear_to_srgb(c.b)};
}

void expect_texel(const Color& got, int i, const std::string& what) {
    EXPECT_NEAR(got.r, texel(i).r, 1e-3f) << what;
    EXPECT_NEAR(got.g, texel(i).g, 1e-3f) << what;
    EXPECT_NEAR(got.b, texel(i).b, 1e-3f) << what;
}

}  // namespace

TEST(GltfTextureTransform, OffsetRotationAndScaleMoveTheTexelSeen) {
    // At texel 0's centre (1/8, 1/2): without the extension texel 0; offset 1/2 adds two
    // texels (texel 2); scale 3 lands on 3/8 (texel 1); rotation π gives (−1/8, −1/2), which
    // repeats to 7/8 (texel 3).
    const Vec2 uv = centre(0);
    expect_texel(seen(base_colour(nullptr), uv), 0, "no extension");
    expect_texel(seen(base_colour(json::object()), uv), 0, "all defaults: the identity");
    expect_texel(seen(base_colour({{"offset", {0.5, 0.0}}}), uv), 2, "offset 0.5");
    expect_texel(seen(base_colour({{"scale", {3.0, 1.0}}}), uv), 1, "scale 3");
    expect_texel(seen(base_colour({{"rotation", std::numbers::pi}}), uv), 3, "rotation π");
}

namespace {

/// The quad rendered whole by the Whitted integrator (the loader's framing camera and
/// default light), 16×12, 1 sample per pixel.
glint::Film render_textured(glint::GltfScene file) {
    const glint::RenderScene prepared(std::move(file.loaded.scene));
    glint::RenderSettings settings;
    settings.width = 16;
    settings.height = 12;
    glint::Film film(settings.width, settings.height);
    glint::WhittedIntegrator(2).render(prepared, settings, film, {});
    return film;
}

/// Σ |a − b| over pixels and channels.
float difference(const glint::Film& a, const glint::Film& b) {
    float sum = 0.0f;
    for (uint32_t y = 0; y < a.height(); ++y)
        for (uint32_t x = 0; x < a.width(); ++x) {
            const Color d = a.at(x, y) - b.at(x, y);
            sum += std::abs(d.r) + std::abs(d.g) + std::abs(d.b);
        }
    return sum;
}

/// base_colour(transform) with texture coordinates spanning [0, 1] once over the quad, so
/// that the camera sees each texel over several pixels (the other tests' coordinates repeat
/// the texture many times, which filtering rightly averages to one colour when rendered).
glint::GltfScene magnified(const json& transform) {
    const auto dir = glint_test::temp_dir();
    glint_test::write_png(dir / "four.png", kTexels);
    json j = glint_test::quad_json_with({{"pbrMetallicRoughness",
                                          {{"baseColorFactor", {1, 1, 1, 1}},
                                           {"metallicFactor", 0},
                                           {"baseColorTexture", info(transform)}}}},
                                        {"four.png"});
    j["extensionsUsed"] = {"KHR_texture_transform"};
    // u = (x + 10)/20 and v = (z + 10)/20 at the quad's corners (−10,·,−10), (−10,·,10),
    // (10,·,10), (10,·,−10).
    std::string bin = glint_test::quad_buffer();
    glint_test::add_quad_attribute(j, bin, "TEXCOORD_0", "VEC2", {0, 0, 0, 1, 1, 1, 1, 0});
    glint_test::write_file(dir / "quad.glb", glint_test::make_glb(j, bin));
    return glint::load_gltf_scene(dir / "quad.glb");
}

}  // namespace

TEST(GltfTextureTransform, TheRenderedQuadChangesWithTheTransformAndNotWithTheIdentity) {
    const glint::Film plain = render_textured(magnified(nullptr));
    EXPECT_EQ(difference(render_textured(magnified(json::object())), plain), 0.0f) << "the identity renders the same";
    for (const json& transform : {json{{"offset", {0.5, 0.0}}}, json{{"scale", {3.0, 1.0}}},
                                  json{{"rotation", std::numbers::pi / 2}}})
        EXPECT_GT(difference(render_textured(magnified(transform)), plain), 1.0f) << transform.dump();
}

TEST(GltfTextureTransform, IsMappedAndTheViewIsNotCountedAsATexture) {
    const auto s = base_colour({{"offset", {0.5, 0.0}}});
    EXPECT_TRUE(s.report.ignored.empty()) << s.report.ignored.front();
    EXPECT_EQ(s.report.textures, 1u);
    EXPECT_EQ(s.loaded.scene.texture_count(), 1u) << "the view is not a texture of its own";
    ASSERT_NE(s.loaded.scene.materials()[0].texture, nullptr);
    EXPECT_TRUE(s.loaded.scene.materials()[0].texture->is_view());
    const auto& mapped = s.report.mapped;
    EXPECT_NE(std::find(mapped.begin(), mapped.end(), "KHR_texture_transform: 1 texture(s) seen through a uv transform"),
              mapped.end())
        << "glint info lists it as mapped";
}

TEST(GltfTextureTransform, AppliesToMetallicRoughnessEmissionAndAlpha) {
    // Base colour, emission (and so the MASK alpha) two texels to the right, the
    // metallic-roughness texture one: at texel 0's centre they show texels 2 and 1.
    const json two = {{"offset", {0.5, 0.0}}}, one = {{"offset", {0.25, 0.0}}};
    const json material = {{"alphaMode", "MASK"},
                           {"emissiveFactor", {1, 1, 1}},
                           {"emissiveTexture", info(two)},
                           {"pbrMetallicRoughness",
                            {{"baseColorTexture", info(two)},
                             {"metallicFactor", 1},
                             {"roughnessFactor", 1},
                             {"metallicRoughnessTexture", info(one)}}}};
    const auto s = load_with_material(material);
    const glint::Material& m = s.loaded.scene.materials()[0];
    // Roughness is the green channel: texel 1's 1 at texel 0, texel 2's 0 at texel 1 (without
    // the extension, 0 and 1).
    EXPECT_NEAR(glint::material_at_hit(m, centre(0), {}).roughness, texel(1).g, 1e-6f);
    EXPECT_NEAR(glint::material_at_hit(m, centre(1), {}).roughness, texel(2).g, 1e-6f);
    ASSERT_NE(m.emission_texture, nullptr);
    const Color e = m.emission_texture->evaluate(centre(0), {});
    expect_texel({glint::linear_to_srgb(e.r), glint::linear_to_srgb(e.g), glint::linear_to_srgb(e.b)}, 2, "emission");
    EXPECT_EQ(m.emission_texture, m.texture) << "one view for one texture, decoding and map";
    EXPECT_EQ(m.alpha_texture, m.texture) << "the mask is the transformed base colour";
    EXPECT_EQ(s.report.textures, 2u) << "one sRGB and one data texture";
}

TEST(GltfTextureTransform, TexCoordOfTheExtensionOverridesTheTextureInfos) {
    const std::string note = "texCoord set other than 0 (baseColorTexture): set 0 used";
    auto noted = [&](const glint::GltfScene& s) {
        for (const auto& line : s.report.ignored)
            if (line.find(note) != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(noted(base_colour({{"texCoord", 1}})));
    json material = {{"pbrMetallicRoughness", {{"baseColorTexture", info({{"texCoord", 0}})}}}};
    material["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    EXPECT_FALSE(noted(load_with_material(material))) << "the extension's texCoord 0 replaces the textureInfo's 1";
}

TEST(GltfTextureTransform, MalformedValuesNameTheirJsonPath) {
    const std::string at = "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform";
    const json bad[] = {json::array({1}),
                        {{"offset", {1}}},
                        {{"offset", {1, "a"}}},
                        {{"scale", 2}},
                        {{"scale", {1, 2, 3}}},
                        {{"rotation", "quarter"}},
                        {{"rotation", 1e39}},
                        {{"texCoord", -1}},
                        {{"texCoord", 0.5}}};
    const char* field[] = {"", ".offset", ".offset", ".scale", ".scale", ".rotation", ".rotation", ".texCoord", ".texCoord"};
    int failed = 0;
    for (std::size_t i = 0; i < std::size(bad); ++i) {
        try {
            (void)base_colour(bad[i]);
            ADD_FAILURE() << "accepted " << bad[i].dump();
        } catch (const glint::SceneError& e) {
            EXPECT_NE(std::string(e.what()).find(at + field[i] + ": "), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("quad.gltf"), std::string::npos) << e.what();
            ++failed;
        }
    }
    EXPECT_EQ(failed, 9);
}
