#pragma once
/// \file Meshes read from a file placed into a scene, one object per placement. Internal:
/// the glTF scene loader and import_mesh_file() share it.

#include "import_notes.h"
#include "mesh_file.h"

#include "glint/scene/scene.h"

#include <functional>
#include <memory>
#include <optional>
#include <unordered_set>
#include <vector>

namespace glint {

/// What place_meshes() added.
struct PlacedMeshes {
    std::size_t objects = 0;
    /// Triangles placed, instances counted each time.
    std::size_t instanced_triangles = 0;
    /// The distinct meshes placed.
    std::unordered_set<const TriangleMesh*> meshes;
    /// Per placement, the object it became (none for a placement skipped).
    std::vector<std::optional<uint32_t>> objects_by_placement;
};

/// Add to `scene` one object per placement whose mesh exists (`meshes[placement.mesh]`),
/// placed by `world_from_file` · file_from_mesh, with scene material `material(mesh index)`.
/// A node with a singular transform (scale 0) is skipped and noted in `notes`: every ray
/// query needs the inverse, and the mesh it would draw is flat or a point anyway.
PlacedMeshes place_meshes(Scene& scene, const std::vector<MeshPlacement>& placements,
                          const std::vector<std::shared_ptr<TriangleMesh>>& meshes, const Transform& world_from_file,
                          const std::function<uint32_t(uint32_t mesh)>& material, ImportNotes& notes);

}  // namespace glint
