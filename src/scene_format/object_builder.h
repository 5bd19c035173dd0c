#pragma once
/// \file The `[[shapes]]` and `[[objects]]` sections: geometry placed in the scene.

#include "glint/assets/mesh_loader.h"
#include "glint/scene_format/param_table.h"
#include "glint/scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glint {

/// Build the named shapes of `[[shapes]]`, then add every `[[objects]]` entry to `scene`
/// (whose materials must already be there). Mesh files go through import_mesh_file with
/// `meshes` (one read per file); its warnings are appended to `warnings`. Throws SceneError at `file:line:column`.
void add_objects(const ParamTable& root, const std::filesystem::path& base_dir, Scene& scene, MeshCache& meshes,
                 std::vector<std::string>& warnings);

/// The sphere, quad, plane, disk, box or heightfield that the keys of `t` describe (`type`
/// already read); throws SceneError at the offending key. A disk without `normal` faces
/// `disk_normal`. Area lights (`[[lights]]`) are built by the same code as objects.
[[nodiscard]] std::shared_ptr<Shape> read_simple_shape(const ParamTable& t, const std::string& type,
                                                       const Vec3& disk_normal = Vec3(0.0f, 1.0f, 0.0f));

/// The index of the scene material named by the string `value`; throws SceneError at the
/// value, suggesting the closest defined name, if there is none.
[[nodiscard]] uint32_t material_by_name(const Scene& scene, const ParamValue& value, std::string_view what);

}  // namespace glint
