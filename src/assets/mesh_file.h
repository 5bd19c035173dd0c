#pragma once
/// \file A mesh file read into Glint meshes (through assimp, or for plain PLY files by Glint
/// itself), before placing it in a scene.
/// Internal: import_mesh_file() and the glTF scene loader share it.

#include "glint/geometry/triangle_mesh.h"
#include "glint/image/image.h"
#include "glint/materials/material.h"
#include "glint/math/transform.h"
#include "glint/scene/asset_defaults.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// One node of the file that draws mesh `mesh`.
struct MeshPlacement {
    uint32_t mesh = 0;
    Matrix4 file_from_mesh = Matrix4::identity();
    std::string node;
};

struct MeshFile {
    /// One per assimp mesh (a glTF primitive); null when it had no usable triangles.
    std::vector<std::shared_ptr<TriangleMesh>> meshes;
    /// The file's material index of each mesh (for glTF: the JSON index, or the count of
    /// JSON materials for "no material").
    std::vector<uint32_t> mesh_materials;
    std::vector<MeshPlacement> placements;
    /// Distinct meshes as the file groups them (a glTF mesh with several primitives is one).
    std::size_t distinct_meshes = 0;
    /// The file's materials as assimp describes them (used for every format but glTF), and
    /// the decoded diffuse texture of each (null for none).
    std::vector<Material> materials;
    std::vector<std::shared_ptr<const Image>> material_images;
    /// The tangent-space normal map of each material (null for none): OBJ's `norm` and
    /// `map_Bump`/`bump` (read as a normal map, as Blender does), FBX's normal maps.
    std::vector<std::shared_ptr<const Image>> material_normal_images;
    /// The up axis the file declares (FBX's GlobalSettings UpAxis, +y/+z/+x), if any.
    std::optional<UpAxis> declared_up;
    /// Problems worked around (dropped triangles, missing textures), one line each.
    std::vector<std::string> warnings;
    /// What the file animates, which Glint draws at rest: names of skinned meshes and of
    /// meshes with morph targets, and the number of animations. Callers word the warnings.
    std::vector<std::string> skinned_meshes;
    std::vector<std::string> morphed_meshes;
    std::size_t animations = 0;
    /// glTF EXT_mesh_gpu_instancing instances placed (read_gltf_geometry).
    std::size_t gpu_instances = 0;
};

/// The warning lines for `file`'s skins, morph targets and animations ("path: ...").
[[nodiscard]] std::vector<std::string> animation_warnings(const std::filesystem::path& path, const MeshFile& file);

/// What the reader does with a triangle it cannot use: one that touches a non-finite
/// vertex position or (where assimp's validation lets it through) indexes past the vertices.
enum class ReadMode {
    /// Refuse the file with the mesh, face or vertex named, and take the geometry as stored:
    /// no materials, no generated normals (load_mesh_data: tests and benchmarks).
    Strict,
    /// Drop the triangle and say so in MeshFile::warnings; convert the file's materials and
    /// give meshes without normals smooth ones (scenes).
    Lenient,
};

/// Read `path`: a plain binary PLY triangle mesh with Glint's own reader (ply_triangles.h),
/// every other file with assimp. Throws SceneError naming the file and the problem when
/// nothing usable is in it, or, in Strict mode, at the first unusable vertex or triangle.
[[nodiscard]] MeshFile read_mesh_file(const std::filesystem::path& path, ReadMode mode);
/// read_mesh_file's reading through assimp, for any file (tests compare the two readers).
[[nodiscard]] MeshFile read_mesh_file_with_assimp(const std::filesystem::path& path, ReadMode mode);

namespace gltf {
struct Document;
}

/// The geometry of a glTF document through assimp (gltf::geometry_glb explains why assimp
/// sees only the geometry); `mesh_materials` are the JSON material indices. No materials
/// are converted. Throws SceneError.
[[nodiscard]] MeshFile read_gltf_geometry(const gltf::Document& doc);

}  // namespace glint
