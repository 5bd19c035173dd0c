#pragma once
/// \file The `[[shapes]]` and `[[objects]]` sections: geometry placed in the scene.

#include "glint/io/param_table.h"
#include "glint/scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glint {

/// Build the named shapes of `[[shapes]]`, then add every `[[objects]]` entry to `scene`
/// (whose materials must already be there). Mesh files go through import_mesh_file; its
/// warnings are appended to `warnings`. Throws SceneError at `file:line:column`.
void add_objects(const ParamTable& root, const std::filesystem::path& base_dir, Scene& scene,
                 std::vector<std::string>& warnings);

/// The index of the scene material named by the string `value`; throws SceneError at the
/// value, suggesting the closest defined name, if there is none.
[[nodiscard]] uint32_t material_by_name(const Scene& scene, const ParamValue& value, std::string_view what);

}  // namespace glint
