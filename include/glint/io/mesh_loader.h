#pragma once
/// \file Mesh files through assimp (OBJ/MTL, PLY, STL, glTF/GLB, FBX, ...).

#include "glint/geometry/triangle_mesh.h"
#include "glint/math/transform.h"
#include "glint/scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// Every triangle of every mesh in the file, merged into one MeshData in file order
/// (vertex and face order and winding as stored; no materials). For tests and benchmarks.
/// Throws SceneError naming the file and the problem.
[[nodiscard]] MeshData load_mesh_data(const std::filesystem::path& path);

struct MeshImportResult {
    std::size_t objects = 0;
    std::size_t triangles = 0;
    std::vector<std::string> warnings;
};

/// Add the file's meshes to `scene` as objects placed by `world_from_file` (node transforms
/// of the file applied below it). With `override_material` every mesh uses that scene
/// material; otherwise the file's materials are converted and added to the scene.
/// Throws SceneError naming the file and the problem.
MeshImportResult import_mesh_file(Scene& scene, const std::filesystem::path& path, const Transform& world_from_file,
                                  std::optional<uint32_t> override_material);

}  // namespace glint
