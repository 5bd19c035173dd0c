#include "gltf_materials.h"

#include "glint/image/image_io.h"
#include "glint/materials/metallic_roughness.h"

#include "glint/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::gltf {

namespace {

Color color3(const nlohmann::json& j, const char* key, Color fallback) {
    if (!j.contains(key) || !j[key].is_array() || j[key].size() < 3) return fallback;
    return {j[key].at(0).get<float>(), j[key].at(1).get<float>(), j[key].at(2).get<float>()};
}

const nlohmann::json& extension(const nlohmann::json& material, const char* name) {
    static const nlohmann::json empty = nlohmann::json::object();
    if (material.contains("extensions") && material.at("extensions").contains(name))
        return material.at("extensions").at(name);
    return empty;
}

}  // namespace

bool is_mapped_material_extension(const std::string& name) {
    return name == "KHR_materials_transmission" || name == "KHR_materials_ior" ||
           name == "KHR_materials_emissive_strength" || name == "KHR_materials_volume" ||
           name == "KHR_materials_specular";
}

void MaterialConverter::convert_all() {
    const std::size_t count = array_size(doc_.json, "materials");
    for (std::size_t i = 0; i < count; ++i) material(int(i));
}

const MaterialInfo& MaterialConverter::material(int index) {
    if (index < 0 || std::size_t(index) >= array_size(doc_.json, "materials")) index = -1;
    auto it = converted_.find(index);
    if (it == converted_.end()) it = converted_.emplace(index, convert(index)).first;
    return it->second;
}

std::shared_ptr<const Image> MaterialConverter::image(int index, ColorEncoding encoding) {
    auto it = images_.find({index, encoding});
    if (it != images_.end()) return it->second;
    std::shared_ptr<const Image> result;
    std::string name;
    try {
        const std::vector<unsigned char> bytes = image_bytes(doc_, index, name);
        result = std::make_shared<const Image>(decode_image(bytes, name, encoding));
    } catch (const std::exception& e) {
        // A missing or broken texture costs the material its texture, not the render.
        notes_.ignored("texture image " + std::to_string(index) + " could not be read: " + json_error_text(e), "");
    }
    images_[{index, encoding}] = result;
    return result;
}

const Texture* MaterialConverter::texture(const nlohmann::json& info, const std::string& material_name,
                                          const char* slot, ColorEncoding encoding) {
    if (!info.is_object() || !info.contains("index")) return nullptr;
    if (integer_or<int>(info, "texCoord", 0) != 0)
        notes_.ignored(std::string("texCoord set other than 0 (") + slot + "): set 0 used", material_name);
    if (info.contains("extensions") && info.at("extensions").contains("KHR_texture_transform"))
        notes_.ignored("KHR_texture_transform (texture offset/scale/rotation)", material_name);
    const int t = integer<int>(info.at("index"));
    auto it = textures_.find({t, encoding});
    if (it != textures_.end()) return it->second;
    const Texture* result = nullptr;
    if (t >= 0 && std::size_t(t) < array_size(doc_.json, "textures")) {
        const auto& tex = doc_.json.at("textures").at(std::size_t(t));
        if (tex.contains("source")) {
            if (auto img = image(integer<int>(tex.at("source")), encoding)) {
                WrapMode wrap = WrapMode::Repeat;
                if (tex.contains("sampler") &&
                    integer<std::size_t>(tex.at("sampler")) < array_size(doc_.json, "samplers")) {
                    const int wrap_s = integer_or<int>(
                        doc_.json.at("samplers").at(integer<std::size_t>(tex.at("sampler"))), "wrapS", 10497);
                    if (wrap_s == 33071) wrap = WrapMode::Clamp;  // CLAMP_TO_EDGE; MIRRORED_REPEAT maps to repeat
                }
                result = scene_.add_texture(std::make_unique<ImageTexture>(std::move(img), wrap));
            }
        } else {
            notes_.ignored("texture without a PNG/JPEG source (e.g. KHR_texture_basisu only)", material_name);
        }
    }
    textures_[{t, encoding}] = result;
    return result;
}

Color MaterialConverter::dielectric_f0(const nlohmann::json& material, float ior, const std::string& name) {
    // KHR_materials_ior: F0 = ((ior − 1)/(ior + 1))², 4 % at the default 1.5 (in double, so
    // that 1.5 gives the float 0.04 exactly, as a file without the extension does).
    const double r = (double(ior) - 1.0) / (double(ior) + 1.0);
    // KHR_materials_specular: tinted by specularColorFactor (clamped to 1) and scaled by
    // specularFactor; the textures that vary them are not read.
    const auto& specular = extension(material, "KHR_materials_specular");
    const Color tint = color3(specular, "specularColorFactor", Color(1.0f));
    const float factor = std::clamp(specular.value("specularFactor", 1.0f), 0.0f, 1.0f);
    if (specular.contains("specularTexture") || specular.contains("specularColorTexture"))
        notes_.ignored("KHR_materials_specular textures (factors used)", name);
    const Color f0 = Color(float(r * r)) * tint;
    return Color(std::min(f0.r, 1.0f), std::min(f0.g, 1.0f), std::min(f0.b, 1.0f)) * factor;
}

Color MaterialConverter::volume_absorption(const nlohmann::json& material, const std::string& name) {
    // KHR_materials_volume: white light keeps attenuationColor after attenuationDistance
    // inside, so σa = −ln(attenuationColor) / attenuationDistance (Beer-Lambert). The
    // thickness the extension gives rasterizers is the real geometry's here.
    const auto& volume = extension(material, "KHR_materials_volume");
    const float distance = volume.value("attenuationDistance", std::numeric_limits<float>::infinity());
    if (volume.contains("thicknessTexture")) notes_.ignored("KHR_materials_volume thicknessTexture (ray-traced thickness used)", name);
    if (!(distance > 0.0f) || !std::isfinite(distance)) return Color(0.0f);
    const Color left = color3(volume, "attenuationColor", Color(1.0f));
    // A channel that keeps nothing absorbs as strongly as one that keeps 1e-6 of it.
    auto sigma = [&](float kept) { return -std::log(std::clamp(kept, 1e-6f, 1.0f)) / distance; };
    return {sigma(left.r), sigma(left.g), sigma(left.b)};
}

MaterialInfo MaterialConverter::convert(int index) {
    static const nlohmann::json default_material = nlohmann::json::object();
    const nlohmann::json& j = index < 0 ? default_material : doc_.json.at("materials").at(std::size_t(index));
    Material m;
    m.name = index < 0 ? "gltf_default" : j.value("name", "material" + std::to_string(index));
    const std::string& name = m.name;
    const nlohmann::json pbr = j.value("pbrMetallicRoughness", nlohmann::json::object());

    Color base(1.0f);
    float alpha = 1.0f;
    if (pbr.contains("baseColorFactor") && pbr.at("baseColorFactor").size() >= 4) {
        base = color3(pbr, "baseColorFactor", base);
        alpha = pbr.at("baseColorFactor").at(3).get<float>();
    }
    const float metallic = std::clamp(pbr.value("metallicFactor", 1.0f), 0.0f, 1.0f);
    const float roughness = std::clamp(pbr.value("roughnessFactor", 1.0f), 0.0f, 1.0f);
    const Texture* base_texture =
        texture(pbr.value("baseColorTexture", nlohmann::json()), name, "baseColorTexture", ColorEncoding::Color);

    // Metallic-roughness on Glint's lobes (glTF 2.0, Appendix B; materials/metallic_roughness.h):
    // one GGX lobe of the file's roughness (alpha = roughness², as glTF defines it) with Schlick
    // F0 = mix(0.04, base, metallic), beside the diffuse base·(1 − metallic). Roughness 0 is a mirror.
    m.ior = extension(j, "KHR_materials_ior").value("ior", 1.5f);
    if (!(m.ior >= 1.0f)) m.ior = 1.0f;  // ior 0 ("no refraction") is not a physical index
    m.dielectric_f0 = dielectric_f0(j, m.ior, name);
    const MetallicRoughnessLobes lobes = metallic_roughness_lobes(base, metallic, m.dielectric_f0);
    m.diffuse = lobes.diffuse;
    m.ambient = m.diffuse;
    m.texture = base_texture;
    m.reflectivity = lobes.reflectivity;
    m.fresnel_mirror = true;
    m.roughness = roughness;
    // A metallicRoughnessTexture makes metalness and roughness vary over the surface (§3.9.2).
    // Its values "MUST be encoded with a linear transfer function" (material.pbrMetallicRoughness
    // schema), so its image is read as data; they multiply the factors at each hit
    // (materials/material_at_hit.h), so the material keeps them.
    m.metallic_roughness_texture = texture(pbr.value("metallicRoughnessTexture", nlohmann::json()), name,
                                           "metallicRoughnessTexture", ColorEncoding::Data);
    m.base_color = base;
    m.metallic = metallic;

    // Emission: factor × KHR_materials_emissive_strength × texture, as radiance.
    const float strength = extension(j, "KHR_materials_emissive_strength").value("emissiveStrength", 1.0f);
    m.emission = color3(j, "emissiveFactor", Color(0.0f)) * strength;
    if (j.contains("emissiveTexture")) {
        m.emission_texture = texture(j.at("emissiveTexture"), name, "emissiveTexture", ColorEncoding::Color);
        if (m.emission.is_black() && m.emission_texture) m.emission_texture = nullptr;  // factor 0 turns it off
    }

    // KHR_materials_transmission + KHR_materials_ior: a dielectric, rough with the same
    // roughness (the extension's transmission lobe shares the specular lobe's roughness, the
    // metallic-roughness texture's included: the Bsdf takes both from material_at_hit).
    const auto& transmission = extension(j, "KHR_materials_transmission");
    m.transparency = std::clamp(transmission.value("transmissionFactor", 0.0f), 0.0f, 1.0f);
    if (transmission.contains("transmissionTexture")) notes_.ignored("transmissionTexture (factor used)", name);
    m.absorption = volume_absorption(j, name);

    MaterialInfo info;
    info.double_sided = j.value("doubleSided", false);
    const std::string alpha_mode = j.value("alphaMode", "OPAQUE");
    if (alpha_mode == "MASK" || alpha_mode == "BLEND") {
        info.alpha_cutoff = alpha_mode == "MASK" ? j.value("alphaCutoff", 0.5f) : 0.5f;
        if (base_texture) {
            info.alpha_mask = base_texture;
            m.alpha_texture = base_texture;
            m.alpha_cutoff = info.alpha_cutoff;
        }
        if (alpha_mode == "BLEND") {
            // No blending in a Whitted tracer: a textured alpha becomes a cut-out and the
            // surface a see-through layer (transparency 1 - alpha, index 1, so rays pass
            // straight on). It is never fully opaque (at least one 8-bit alpha step), so,
            // like every Glint dielectric, it casts no shadow: the rasterizers glTF targets
            // leave blended surfaces out of their shadow maps, and lamps model their shades so.
            notes_.ignored("alphaMode BLEND (approximated: see-through layer without shadows, cut-out at 0.5)", name);
            if (m.transparency == 0.0f) {
                m.transparency = std::max(1.0f - std::clamp(alpha, 0.0f, 1.0f), 1.0f / 255.0f);
                m.ior = 1.0f;
            }
        }
    }
    if (j.contains("normalTexture")) notes_.ignored("normalTexture (no normal mapping; geometric normals used)", name);
    if (j.contains("occlusionTexture")) notes_.ignored("occlusionTexture (no ambient occlusion)", name);
    if (j.contains("extensions"))
        for (const auto& [ext, value] : j.at("extensions").items())
            if (!is_mapped_material_extension(ext)) notes_.ignored("material extension " + ext, name);

    info.scene_material = scene_.add_material(std::move(m));
    return info;
}

}  // namespace glint::gltf
