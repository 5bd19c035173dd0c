// glTF material conversion (docs/assets.md): metallic → Fresnel mirror tinted by the base
// colour, roughness → its GGX lobe, transmission + IOR → dielectric (rough with the same
// roughness), emission, alpha modes, double-sided.

#include "gltf_test_files.h"
#include "png_file.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/materials/bsdf.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>


namespace {

using nlohmann::json;

/// Load the quad with `material` as its only material.
glint::GltfScene quad_with_material(const json& material, const json& extensions_used = json::array()) {
    json j = glint_test::quad_json("quad.bin");
    j["materials"][0] = material;
    if (!extensions_used.empty()) j["extensionsUsed"] = extensions_used;
    return glint::load_gltf_scene(glint_test::write_gltf(glint_test::temp_dir(), "quad", j));
}

TEST(GltfMaterials, SmoothMetalIsAMirrorTintedByTheBaseColour) {
    const auto s = quad_with_material(
        {{"name", "gold"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {1.0, 0.8, 0.3, 1.0}}, {"metallicFactor", 1}, {"roughnessFactor", 0}}}});
    const glint::Material& m = s.loaded.scene.materials()[0];
    EXPECT_EQ(m.name, "gold");
    EXPECT_TRUE(m.fresnel_mirror);
    EXPECT_EQ(m.reflectivity, glint::Color(1.0f, 0.8f, 0.3f)) << "F0 = base colour";
    EXPECT_EQ(m.diffuse, glint::Color(0.0f)) << "metals have no diffuse part";
    EXPECT_EQ(m.roughness, 0.0f);
    EXPECT_EQ(m.transparency, 0.0f);
}

TEST(GltfMaterials, DielectricHasFourPercentFresnelAndDiffuseBase) {
    const auto s = quad_with_material(
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}, {"metallicFactor", 0}, {"roughnessFactor", 0}}}});
    const glint::Material& m = s.loaded.scene.materials()[0];
    EXPECT_NEAR(m.reflectivity.g, 0.04f, 1e-6f);
    EXPECT_EQ(m.diffuse, glint::Color(0.2f, 0.4f, 0.6f));
    EXPECT_EQ(m.ambient, m.diffuse);
}

TEST(GltfMaterials, RoughMetalIsAGlossyConductorWithTheBaseColourAsF0) {
    // The whole reflection stays in the GGX lobe of the file's roughness: no diffuse share,
    // no Blinn-Phong stand-in (the conversion before the microfacet lobes existed).
    const auto s = quad_with_material(
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.9, 0.6, 0.3, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0.25}}}});
    const glint::Material& m = s.loaded.scene.materials()[0];
    EXPECT_FLOAT_EQ(m.roughness, 0.25f);
    EXPECT_TRUE(m.fresnel_mirror);
    EXPECT_EQ(m.reflectivity, glint::Color(0.9f, 0.6f, 0.3f)) << "F0 = base colour at any roughness";
    EXPECT_EQ(m.diffuse, glint::Color(0.0f));
    EXPECT_EQ(m.specular, glint::Color(0.0f));
}

TEST(GltfMaterials, RoughDielectricPartIsDiffusePlusAFourPercentGlossyLobe) {
    const auto s = quad_with_material(
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.5}}}});
    const glint::Material& m = s.loaded.scene.materials()[0];
    EXPECT_FLOAT_EQ(m.roughness, 0.5f);
    // diffuse = base·(1 − metallic); F0 = mix(0.04, base, metallic).
    EXPECT_NEAR(m.diffuse.r, 0.2f * 0.75f, 1e-6f);
    EXPECT_NEAR(m.diffuse.b, 0.6f * 0.75f, 1e-6f);
    EXPECT_NEAR(m.reflectivity.r, 0.04f * 0.75f + 0.2f * 0.25f, 1e-6f);
    EXPECT_NEAR(m.reflectivity.b, 0.04f * 0.75f + 0.6f * 0.25f, 1e-6f);
    EXPECT_TRUE(m.fresnel_mirror);
    EXPECT_EQ(m.specular, glint::Color(0.0f));
}

TEST(GltfMaterials, TransmissionRoughnessMakesARoughDielectric) {
    const auto s = quad_with_material({{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0.4}}},
                                       {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}},
                                      {"KHR_materials_transmission"});
    const glint::Material& m = s.loaded.scene.materials()[0];
    EXPECT_FLOAT_EQ(m.transparency, 1.0f);
    EXPECT_FLOAT_EQ(m.roughness, 0.4f);
    // At a hit, the glass is the rough dielectric (no delta lobes left).
    const glint::Vec3 up(0, 0, 1);
    const glint::Bsdf bsdf(m, glint::material_at_hit(m, glint::Vec2(), glint::Vec3()), up, up, glint::normalize(glint::Vec3(0.3f, 0, 1)),
                           {1.0f, m.ior});
    EXPECT_TRUE(bsdf.has_glossy_lobes());
    EXPECT_FALSE(bsdf.specular().refracted);
}

TEST(GltfMaterials, TransmissionAndIorMakeADielectric) {
    const auto s = quad_with_material(
        {{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0}}},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_ior", {{"ior", 1.33}}}}}},
        {"KHR_materials_transmission", "KHR_materials_ior"});
    const glint::Material& m = s.loaded.scene.materials()[0];
    EXPECT_TRUE(m.is_dielectric());
    EXPECT_FLOAT_EQ(m.transparency, 1.0f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_TRUE(s.report.ignored.empty()) << s.report.ignored.front();
}

TEST(GltfMaterials, EmissionIsFactorTimesStrength) {
    const auto s =
        quad_with_material({{"emissiveFactor", {1.0, 0.5, 0.0}},
                            {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}});
    EXPECT_EQ(s.loaded.scene.materials()[0].emission, glint::Color(4.0f, 2.0f, 0.0f));
}

TEST(GltfMaterials, DefaultMaterialIsARoughWhiteMetal) {
    json j = glint_test::quad_json("quad.bin");
    j.erase("materials");
    j["meshes"][0]["primitives"][0].erase("material");
    const auto s = glint::load_gltf_scene(glint_test::write_gltf(glint_test::temp_dir(), "quad", j));
    EXPECT_TRUE(s.report.default_material);
    EXPECT_EQ(s.report.materials, 0u);
    const glint::Material& m = s.loaded.scene.material(s.loaded.scene.objects()[0].material);
    // The spec's default: white, metallic 1, roughness 1; a rough white conductor, no diffuse.
    EXPECT_EQ(m.diffuse, glint::Color(0.0f));
    EXPECT_EQ(m.reflectivity, glint::Color(1.0f));
    EXPECT_TRUE(m.fresnel_mirror);
    EXPECT_EQ(m.roughness, 1.0f);
}

TEST(GltfMaterials, AlphaMaskCutsTheMeshAndBlendCastsNoShadow) {
    const auto dir = glint_test::temp_dir();
    // A 1×1 RGBA PNG with alpha 0, as a data URI: the cut-out removes the whole quad.
    glint_test::write_png8(dir / "clear.png", 1, 1, 4, {255, 255, 255, 0});
    const std::string transparent_png = "clear.png";
    json j = glint_test::quad_json("quad.bin");
    // Texture coordinates: any 4 VEC2s will do (the texture is uniform); reuse the positions' bytes.
    j["accessors"].push_back({{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
    j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
    j["images"] = json::array({{{"uri", transparent_png}}});
    j["textures"] = json::array({{{"source", 0}}});
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    j["materials"][0]["alphaMode"] = "MASK";
    j["materials"][0]["alphaCutoff"] = 0.3;
    j["materials"][0]["doubleSided"] = true;
    auto s = glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", j));
    const auto& mesh = dynamic_cast<const glint::TriangleMesh&>(*s.loaded.scene.objects()[0].shape);
    ASSERT_NE(mesh.alpha_mask(), nullptr);
    EXPECT_FLOAT_EQ(s.loaded.scene.materials()[0].alpha_cutoff, 0.3f);
    glint::Scene& scene = s.loaded.scene;
    const glint::RenderScene prepared(std::move(scene));
    glint::Ray down(glint::Vec3(0.5f, 1.0f, 0.5f), glint::Vec3(0.0f, -1.0f, 0.0f));
    glint::Hit hit;
    EXPECT_FALSE(prepared.intersect(down, hit)) << "alpha 0 < cutoff: the quad is cut away";
    EXPECT_FALSE(prepared.occluded(glint::Ray(glint::Vec3(0.5f, 1.0f, 0.5f), glint::Vec3(0.0f, -1.0f, 0.0f))));

    const auto blend =
        quad_with_material({{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}}});
    EXPECT_TRUE(blend.loaded.scene.materials()[0].is_dielectric()) << "see-through layer: no shadow";
    EXPECT_FLOAT_EQ(blend.loaded.scene.materials()[0].ior, 1.0f);
}

}  // namespace
