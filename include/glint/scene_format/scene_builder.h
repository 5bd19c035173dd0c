#pragma once
/// \file From a parsed scene description (ParamTable tree) to a Scene and its render settings.
/// Independent of the file syntax: the TOML front end produces the tree.

#include "glint/scene/loaded_scene.h"
#include "glint/scene_format/param_table.h"

#include <filesystem>
#include <functional>
#include <memory>

namespace glint {

/// `[[objects]]` entries handed over one at a time, after the ones in the root: each call
/// returns the next (named "objects[i]" like the root's own), or null after the last. A
/// front end that reads a large file this way never holds all its objects' tables.
using MoreObjects = std::function<std::shared_ptr<const ParamTable>()>;

/// Build everything docs/scene-format.md describes. Relative file names resolve against
/// `base_dir`. Throws SceneError at `file:line:column` for every mistake, including keys
/// no section understands.
[[nodiscard]] LoadedScene build_scene(const ParamTable& root, const std::filesystem::path& base_dir,
                                      const MoreObjects& more_objects = {});

}  // namespace glint
