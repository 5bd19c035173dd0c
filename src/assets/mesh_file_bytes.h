#pragma once
/// \file A MeshFile as flat bytes: how the import child process (isolated_import.h) hands
/// the meshes, materials and textures it read back to Glint. Internal to src/assets.

#include "mesh_file.h"

#include <string>
#include <string_view>

namespace glint {

[[nodiscard]] std::string to_bytes(const MeshFile& file);

/// The MeshFile `bytes` describe. Throws SceneError "`context`: ..." when they are cut short
/// or inconsistent (a mesh that does not validate, an image of the wrong size).
[[nodiscard]] MeshFile mesh_file_from_bytes(std::string_view bytes, const std::string& context);

}  // namespace glint
