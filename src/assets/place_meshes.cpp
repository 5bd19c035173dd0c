#include "place_meshes.h"

#include <stdexcept>

namespace glint {

PlacedMeshes place_meshes(Scene& scene, const std::vector<MeshPlacement>& placements,
                          const std::vector<std::shared_ptr<TriangleMesh>>& meshes, const Transform& world_from_file,
                          const std::function<uint32_t(uint32_t mesh)>& material, ImportNotes& notes) {
    PlacedMeshes placed;
    for (const MeshPlacement& placement : placements) {
        placed.objects_by_placement.emplace_back();
        // A projective node matrix places nothing meaningfully (and Glint's transforms are affine).
        if (!placement.file_from_mesh.is_affine()) {
            notes.ignored("node with a projective transform (last row not 0, 0, 0, 1)", placement.node);
            continue;
        }
        Transform file_from_mesh;
        try {
            file_from_mesh = Transform(placement.file_from_mesh);
        } catch (const std::invalid_argument&) {
            notes.ignored("node with a singular transform (scale 0)", placement.node);
            continue;
        }
        // Null for a mesh without triangles, or one a cached file never placed (a
        // singular node's) and so did not keep.
        const auto& mesh = meshes[placement.mesh];
        if (!mesh) continue;
        const Transform world_from_mesh = world_from_file * file_from_mesh;
        // A finite mesh under a huge transform can leave float range: infinite vertices
        // would poison the BVH build and every ray that reaches them (found by fuzz/fuzz_gltf).
        const Bounds3 world_bounds = world_from_mesh.bounds(mesh->bounds());
        if (!is_finite(world_bounds.lo) || !is_finite(world_bounds.hi)) {
            notes.ignored("node placing its mesh beyond the range of float coordinates (a huge transform)",
                          placement.node);
            continue;
        }
        placed.objects_by_placement.back() =
            scene.add_object(mesh, material(placement.mesh), world_from_mesh, placement.node);
        ++placed.objects;
        placed.instanced_triangles += mesh->triangle_count();
        placed.meshes.insert(mesh.get());
    }
    return placed;
}

}  // namespace glint
