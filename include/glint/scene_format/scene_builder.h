#pragma once
/// \file From a parsed scene description (ParamTable tree) to a Scene and its render settings.
/// Independent of the file syntax: the TOML front end produces the tree.

#include "glint/scene/loaded_scene.h"
#include "glint/scene_format/param_table.h"

#include <filesystem>

namespace glint {

/// Build everything docs/scene-format.md describes. Relative file names resolve against
/// `base_dir`. Throws SceneError at `file:line:column` for every mistake, including keys
/// no section understands.
[[nodiscard]] LoadedScene build_scene(const ParamTable& root, const std::filesystem::path& base_dir);

}  // namespace glint
