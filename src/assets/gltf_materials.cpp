#include "gltf_materials.h"

#include "glint/image/image_io.h"
#include "glint/materials/metallic_roughness.h"
#include "glint/materials/uv_transform_texture.h"

#include "glint/diagnostics.h"

#include <algorithm>
#include <array>
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

/// A value as an error message shows it: numbers and short arrays as written, anything
/// else by its type (it may be large or deeply nested).
std::string shown(const nlohmann::json& value) {
    const std::string text = value.dump();
    return text.size() <= 40 ? text : std::string(value.type_name());
}

/// True if `value` is a number a float holds (finite, at most FLT_MAX: a cast of a larger
/// double is undefined), stored in `out`.
bool finite_float(const nlohmann::json& value, float& out) {
    if (!value.is_number()) return false;
    const double d = value.get<double>();
    if (!std::isfinite(d) || std::abs(d) > double(std::numeric_limits<float>::max())) return false;
    out = float(d);
    return true;
}

/// `object[key]` as two finite floats, `fallback` when absent; SceneError naming `where.key`
/// otherwise (the KHR_texture_transform schema: "number[2]").
Vec2 two_numbers(const Document& doc, const nlohmann::json& object, const char* key, Vec2 fallback,
                 const std::string& where) {
    if (!object.contains(key)) return fallback;
    const nlohmann::json& value = object.at(key);
    Vec2 result;
    if (!value.is_array() || value.size() != 2 || !finite_float(value[0], result.x) ||
        !finite_float(value[1], result.y))
        fail(doc.path, where + "." + key + ": " + shown(value) + " (expected two finite numbers)");
    return result;
}

/// The six numbers of a map, to tell maps apart in a cache.
std::array<float, 6> coefficients(const UvAffineMap& map) {
    return {map.m[0][0], map.m[0][1], map.m[0][2], map.m[1][0], map.m[1][1], map.m[1][2]};
}

/// The uv map of textureInfo `info` at JSON path `where` from its KHR_texture_transform
/// (T·R·S, materials/uv_transform_texture.h), none without the extension; the extension's
/// texCoord replaces `tex_coord`. Malformed values are SceneErrors naming their JSON path.
std::optional<UvAffineMap> texture_transform(const Document& doc, const nlohmann::json& info,
                                             const std::string& where, int& tex_coord) {
    if (!info.contains("extensions") || !info.at("extensions").contains("KHR_texture_transform"))
        return std::nullopt;
    const std::string at = where + ".extensions.KHR_texture_transform";
    const nlohmann::json& ext = info.at("extensions").at("KHR_texture_transform");
    if (!ext.is_object()) fail(doc.path, at + ": " + shown(ext) + " (expected an object)");
    const Vec2 offset = two_numbers(doc, ext, "offset", Vec2(0.0f, 0.0f), at);
    const Vec2 scale = two_numbers(doc, ext, "scale", Vec2(1.0f, 1.0f), at);
    float rotation = 0.0f;
    if (ext.contains("rotation")) {
        const nlohmann::json& r = ext.at("rotation");
        if (!finite_float(r, rotation))
            fail(doc.path, at + ".rotation: " + shown(r) + " (expected a finite number of radians)");
    }
    // "texCoord: overrides the textureInfo texCoord value if supplied" (the extension's README).
    if (ext.contains("texCoord")) {
        const nlohmann::json& t = ext.at("texCoord");
        if (!t.is_number_integer() || t.get<long long>() < 0)
            fail(doc.path, at + ".texCoord: " + shown(t) + " (expected an integer >= 0)");
        tex_coord = int(std::min<long long>(t.get<long long>(), std::numeric_limits<int>::max()));
    }
    return UvAffineMap::offset_rotation_scale(offset, rotation, scale);
}

}  // namespace

bool is_mapped_material_extension(const std::string& name) {
    return name == "KHR_materials_transmission" || name == "KHR_materials_ior" ||
           name == "KHR_materials_emissive_strength" || name == "KHR_materials_volume" ||
           name == "KHR_materials_specular" || name == "KHR_texture_transform";
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
                                          const std::string& where, ColorEncoding encoding) {
    if (!info.is_object() || !info.contains("index")) return nullptr;
    int tex_coord = integer_or<int>(info, "texCoord", 0);
    const std::optional<UvAffineMap> transform = texture_transform(doc_, info, where, tex_coord);
    if (tex_coord != 0) {
        const std::string slot = where.substr(where.find_last_of('.') + 1);
        notes_.ignored("texCoord set other than 0 (" + slot + "): set 0 used", material_name);
    }
    const Texture* base = image_texture(integer<int>(info.at("index")), material_name, encoding);
    // The identity leaves the texture as it is (offset 0, rotation 0, scale 1 are defaults).
    if (!base || !transform || *transform == UvAffineMap{}) return base;
    // One view per texture, decoding and map, owned by the scene beside the texture it maps.
    const auto key = std::make_pair(base, coefficients(*transform));
    auto it = views_.find(key);
    if (it == views_.end())
        it = views_.emplace(key, scene_.add_texture(std::make_unique<UvTransformTexture>(base, *transform))).first;
    return it->second;
}

const Texture* MaterialConverter::image_texture(int t, const std::string& material_name, ColorEncoding encoding) {
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
    // JSON paths of the textureInfo objects, for errors in their KHR_texture_transform.
    const std::string at = "materials[" + std::to_string(index) + "]";
    const Texture* base_texture = texture(pbr.value("baseColorTexture", nlohmann::json()), name,
                                          at + ".pbrMetallicRoughness.baseColorTexture", ColorEncoding::Color);

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
                                           at + ".pbrMetallicRoughness.metallicRoughnessTexture", ColorEncoding::Data);
    m.base_color = base;
    m.metallic = metallic;

    // Emission: factor × KHR_materials_emissive_strength × texture, as radiance.
    const float strength = extension(j, "KHR_materials_emissive_strength").value("emissiveStrength", 1.0f);
    m.emission = color3(j, "emissiveFactor", Color(0.0f)) * strength;
    if (j.contains("emissiveTexture")) {
        m.emission_texture = texture(j.at("emissiveTexture"), name, at + ".emissiveTexture", ColorEncoding::Color);
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
    // normalTexture (glTF 2.0 §3.9.3): tangent-space normals, linear, x and y scaled by `scale`,
    // in the frame of the TANGENT attribute or, without one, of MikkTSpace tangents
    // (geometry/tangent_space.h computes them for every mesh with uvs and normals).
    if (j.contains("normalTexture")) {
        const nlohmann::json& normal_info = j.at("normalTexture");
        m.normal_texture = texture(normal_info, name, at + ".normalTexture", ColorEncoding::Data);
        if (m.normal_texture && m.normal_texture->channel_count() < 3)
            fail(doc_.path, at + ".normalTexture: its image has " + std::to_string(m.normal_texture->channel_count()) +
                                " channel(s) (expected three, RGB: a tangent-space normal map)");
        if (normal_info.is_object() && normal_info.contains("scale")) {
            const nlohmann::json& scale = normal_info.at("scale");
            if (!scale.is_number() || !std::isfinite(scale.get<double>()))
                fail(doc_.path, at + ".normalTexture.scale: " + shown(scale) + " (expected a finite number)");
            m.normal_scale = scale.get<float>();
        }
    }
    if (j.contains("occlusionTexture")) notes_.ignored("occlusionTexture (no ambient occlusion)", name);
    if (j.contains("extensions"))
        for (const auto& [ext, value] : j.at("extensions").items())
            if (!is_mapped_material_extension(ext)) notes_.ignored("material extension " + ext, name);

    info.scene_material = scene_.add_material(std::move(m));
    return info;
}

}  // namespace glint::gltf
