#pragma once
/// \file glTF metallic-roughness materials to Glint's Whitted material (docs/assets.md). Internal.

#include "gltf_document.h"
#include "import_notes.h"

#include "glint/image/image_io.h"
#include "glint/scene/scene.h"

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace glint::gltf {

/// Material extensions, and KHR_texture_transform on their textures, whose content the
/// converter reads (fully or in part, docs/assets.md).
[[nodiscard]] bool is_mapped_material_extension(const std::string& name);

/// A converted material and what the mesh using it must know.
struct MaterialInfo {
    uint32_t scene_material = 0;
    /// alphaMode MASK (and BLEND with a textured alpha): the mesh's cut-out mask.
    const Texture* alpha_mask = nullptr;
    float alpha_cutoff = 0.5f;
    bool double_sided = false;
};

class MaterialConverter {
public:
    MaterialConverter(const Document& doc, Scene& scene, ImportNotes& notes)
        : doc_(doc), scene_(scene), notes_(notes) {}

    /// Convert every material of the file into the scene, in file order.
    void convert_all();
    /// Material `index` of the file (converting it if needed); -1 or out of range gives
    /// glTF's default material (white, metallic 1, roughness 1 per spec; see docs/assets.md).
    const MaterialInfo& material(int index);
    /// Distinct textures added to the scene.
    [[nodiscard]] std::size_t texture_count() const {
        return std::size_t(std::count_if(textures_.begin(), textures_.end(), [](const auto& t) { return t.second; }));
    }
    /// Distinct KHR_texture_transform views (a texture, decoding and map each) added to the scene.
    [[nodiscard]] std::size_t transformed_view_count() const { return views_.size(); }

private:
    MaterialInfo convert(int index);
    /// The non-metal part's F0 from KHR_materials_ior and KHR_materials_specular.
    Color dielectric_f0(const nlohmann::json& material, float ior, const std::string& name);
    /// σa from KHR_materials_volume (black without it).
    Color volume_absorption(const nlohmann::json& material, const std::string& name);
    /// Texture `info` ({"index", "texCoord", "extensions"}, at JSON path `where`) as a scene
    /// texture, its image decoded with `encoding` (sRGB colour, or linear data such as
    /// metalness and roughness), seen through its KHR_texture_transform if it has one; null
    /// (with a warning) when it cannot be decoded.
    const Texture* texture(const nlohmann::json& info, const std::string& material_name, const std::string& where,
                           ColorEncoding encoding);
    /// Texture `index` of the file decoded with `encoding`, untransformed (cached).
    const Texture* image_texture(int index, const std::string& material_name, ColorEncoding encoding);
    std::shared_ptr<const Image> image(int index, ColorEncoding encoding);

    const Document& doc_;
    Scene& scene_;
    ImportNotes& notes_;
    std::map<int, MaterialInfo> converted_;
    /// By glTF index and encoding: one image may be both colour and data (a packed texture
    /// used as base colour by one material and as metallic-roughness by another).
    std::map<std::pair<int, ColorEncoding>, const Texture*> textures_;
    std::map<std::pair<int, ColorEncoding>, std::shared_ptr<const Image>> images_;
    /// KHR_texture_transform views (UvTransformTexture) by the texture they map and their map's
    /// coefficients: textureInfos that transform a texture alike share one view.
    std::map<std::pair<const Texture*, std::array<float, 6>>, const Texture*> views_;
};

}  // namespace glint::gltf
