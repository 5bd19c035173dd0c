#pragma once
/// \file Mesh files through assimp (OBJ/MTL, PLY, STL, glTF/GLB, FBX, ...).

#include "glint/geometry/triangle_mesh.h"
#include "glint/math/transform.h"
#include "glint/scene/asset_defaults.h"
#include "glint/scene/loaded_scene.h"
#include "glint/scene/scene.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// Every triangle of every mesh in the file, merged into one MeshData in file order
/// (positions and indices only; vertex and face order and winding as stored; node
/// transforms not applied). For tests and benchmarks, so strict: a non-finite vertex or an
/// index past the vertices is a SceneError naming the file, the mesh and the vertex or
/// face, as is a file without triangles.
[[nodiscard]] MeshData load_mesh_data(const std::filesystem::path& path);

struct MeshImportResult {
    std::size_t objects = 0;
    /// Triangles placed by this call (instances counted each time).
    std::size_t triangles = 0;
    /// True if the file was already loaded (through the cache) and only placed again.
    bool reused = false;
    std::vector<std::string> warnings;
    /// The up axis the file declares (FBX), if any.
    std::optional<UpAxis> declared_up;
};

class MeshCache;

/// Add the file's meshes to `scene` as objects placed by `world_from_file` (node transforms
/// of the file applied below it). With `override_material` every mesh uses that scene
/// material; otherwise the file's materials are converted and added to the scene (glTF
/// files through the same conversion as `glint render model.glb`, docs/assets.md).
/// `cache` remembers the files read for this scene: repeated calls for one path read the
/// file once and place its meshes again as instances. Throws SceneError naming the file and
/// the problem; problems it can work around (bad triangles, a missing texture) become
/// warnings in the result.
MeshImportResult import_mesh_file(Scene& scene, const std::filesystem::path& path, const Transform& world_from_file,
                                  std::optional<uint32_t> override_material, MeshCache& cache);

/// Files already read for one scene: each file is read once and its meshes (and, once
/// converted, its materials) are shared by every later placement of the same path.
/// Use one cache per Scene (it holds scene material indices), owned by whoever loads it. It holds the meshes weakly
/// (the scene owns them): an entry whose meshes all died is read again.
class MeshCache {
public:
    MeshCache();
    MeshCache(MeshCache&&) noexcept;
    MeshCache& operator=(MeshCache&&) noexcept;
    ~MeshCache();

    /// Number of distinct files read (live or not).
    [[nodiscard]] std::size_t size() const { return entries_.size(); }

private:
    friend MeshImportResult import_mesh_file(Scene&, const std::filesystem::path&, const Transform&,
                                             std::optional<uint32_t>, MeshCache&);
    struct Entry;  // one file's meshes and converted materials (mesh_loader.cpp)
    /// The live entry for `path` (canonical form), null if not read yet or stale.
    [[nodiscard]] Entry* find(const std::filesystem::path& path) const;
    Entry& insert(const std::filesystem::path& path, std::unique_ptr<Entry> entry);
    /// `path` in the canonical form that keys the entries, resolved on disk once per path.
    [[nodiscard]] const std::filesystem::path& canonical(const std::filesystem::path& path);

    std::map<std::string, std::unique_ptr<Entry>> entries_;
    std::map<std::string, std::filesystem::path> canonical_paths_;
};

/// A bare mesh file (PLY, OBJ, STL, FBX...) as a scene: its meshes and materials, a framing
/// camera and the default lighting, 640×480. The camera stands upright for `up`, else for
/// the axis the file declares (FBX), else for +y. Throws SceneError.
[[nodiscard]] LoadedScene load_mesh_scene(const std::filesystem::path& path, std::optional<UpAxis> up = std::nullopt);

}  // namespace glint
