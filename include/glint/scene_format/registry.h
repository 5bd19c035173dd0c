#pragma once
/// \file The types a scene file can name, one explicit table per kind: `type = "sphere"`
/// finds the sphere's factory, which lives beside the Sphere class and reads its own keys
/// from the ParamTable (pbrt-v4's Sphere::Create, tungsten's PrimitiveFactory).
///
/// The tables are plain arrays in src/scene_format/registry.cpp. There is no
/// self-registration from static initialisers: a static library drops object files that
/// nothing references, and their types would silently go missing. A new type is one line
/// in its table; the lists of valid names in error messages come from the same table.

#include "glint/materials/material.h"
#include "glint/scene_format/param_table.h"

#include <algorithm>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace glint {

class BuildContext;
class Shape;
class Texture;

/// `[[objects]]`, `[[shapes]]`: reads the keys of one shape; throws SceneError at a bad key.
struct ShapeType {
    std::string_view name;
    std::shared_ptr<Shape> (*create)(const ParamTable& params, const BuildContext& context);
};

/// `[[lights]]`: reads the keys of one light and adds it to the context's scene (an area
/// light also adds the object it is).
struct LightType {
    std::string_view name;
    void (*add)(const ParamTable& params, BuildContext& context);
};

/// `[[textures]]`: reads the keys of one texture (`name`, `uv_scale` and `uv_offset` are
/// the section's).
struct TextureType {
    std::string_view name;
    std::unique_ptr<Texture> (*create)(const ParamTable& params, BuildContext& context);
};

/// `[[materials]]`: reads the keys of one material (`name` is the section's).
struct MaterialType {
    std::string_view name;
    Material (*create)(const ParamTable& params, const BuildContext& context);
};

[[nodiscard]] std::span<const ShapeType> shape_types();
[[nodiscard]] std::span<const LightType> light_types();
[[nodiscard]] std::span<const TextureType> texture_types();
[[nodiscard]] std::span<const MaterialType> material_types();

/// The names of a table's types, in table order (for `ParamTable::choice` and messages).
template <class Type>
[[nodiscard]] std::vector<std::string_view> type_names(std::span<const Type> types) {
    std::vector<std::string_view> names;
    for (const Type& t : types) names.push_back(t.name);
    return names;
}

/// The type that the `type` key of `params` names (`fallback` when absent; an empty
/// fallback makes the key required). Throws SceneError listing the valid names, with the
/// closest one as a suggestion.
template <class Type>
[[nodiscard]] const Type& chosen_type(const ParamTable& params, std::span<const Type> types,
                                      std::string_view fallback = {}) {
    const std::string name = params.choice("type", type_names(types), fallback);
    return *std::find_if(types.begin(), types.end(), [&](const Type& type) { return type.name == name; });
}

}  // namespace glint
