#pragma once
/// \file Glint's own scene format (TOML): docs/scene-format.md lists every key.

#include "glint/scene_file.h"

#include <filesystem>
#include <string_view>

namespace glint {

/// Parse a scene file. Relative paths inside it resolve against its folder. Throws
/// SceneError with `file:line:column:` for every mistake, including unknown keys.
[[nodiscard]] LoadedScene load_toml_scene(const std::filesystem::path& path);

/// Parse scene text; `source_name` names it in errors and `base_dir` resolves its paths.
[[nodiscard]] LoadedScene load_toml_scene_string(std::string_view text, const std::string& source_name,
                                                 const std::filesystem::path& base_dir);

}  // namespace glint
