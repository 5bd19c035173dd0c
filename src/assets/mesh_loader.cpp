#include "glint/assets/mesh_loader.h"

#include "gltf_document.h"
#include "gltf_materials.h"
#include "mesh_file.h"
#include "place_meshes.h"

#include "glint/diagnostics.h"
#include "glint/scene/asset_defaults.h"
#include "glint/util/file_extension.h"

#include <algorithm>

namespace glint {

/// One file read for one scene. The meshes are held weakly: the scene's objects own them,
/// so a cache never keeps a dead scene's geometry in memory, and an entry whose meshes are
/// all gone is stale (read again).
struct MeshCache::Entry {
    /// The file as read; its `meshes` are moved out into `meshes` below after placing.
    MeshFile file;
    std::vector<std::weak_ptr<TriangleMesh>> meshes;
    bool is_gltf = false;
    /// Scene material per file material (filled on the first placement without override).
    std::optional<std::vector<uint32_t>> scene_materials;

    [[nodiscard]] bool alive() const {
        return std::any_of(meshes.begin(), meshes.end(), [](const auto& m) { return !m.expired(); });
    }
};

MeshCache::MeshCache() = default;
MeshCache::MeshCache(MeshCache&&) noexcept = default;
MeshCache& MeshCache::operator=(MeshCache&&) noexcept = default;
MeshCache::~MeshCache() = default;

MeshCache::Entry* MeshCache::find(const std::filesystem::path& path) const {
    const auto it = entries_.find(path.string());
    return it == entries_.end() || !it->second->alive() ? nullptr : it->second.get();
}

MeshCache::Entry& MeshCache::insert(const std::filesystem::path& path, std::unique_ptr<Entry> entry) {
    return *(entries_[path.string()] = std::move(entry));
}

const std::filesystem::path& MeshCache::canonical(const std::filesystem::path& path) {
    auto [it, inserted] = canonical_paths_.try_emplace(path.string());
    if (inserted) {
        std::error_code ec;
        const auto resolved = std::filesystem::weakly_canonical(path, ec);
        it->second = ec ? path.lexically_normal() : resolved;
    }
    return it->second;
}

namespace {

bool has_gltf_extension(const std::filesystem::path& path) {
    const std::string ext = lower_case_extension(path);
    return ext == ".gltf" || ext == ".glb";
}

/// Convert `file`'s materials into `scene`; returns the scene material of each file material.
/// A glTF file's materials come from its document `gltf` (null for other formats) and may
/// put alpha masks on `meshes`.
std::vector<uint32_t> add_file_materials(Scene& scene, const MeshFile& file, const gltf::Document* gltf,
                                         const std::vector<std::shared_ptr<TriangleMesh>>& meshes, ImportNotes& notes) {
    std::vector<uint32_t> result;
    if (gltf) {
        gltf::MaterialConverter converter(*gltf, scene, notes);
        for (std::size_t m = 0; m < meshes.size(); ++m) {
            const uint32_t file_material = file.mesh_materials[m];
            if (result.size() <= file_material) result.resize(file_material + 1, 0);
            const gltf::MaterialInfo& info = converter.material(int(file_material));
            result[file_material] = info.scene_material;
            if (meshes[m] && info.alpha_mask) meshes[m]->set_alpha_mask(info.alpha_mask, info.alpha_cutoff);
        }
        return result;
    }
    for (std::size_t i = 0; i < file.materials.size(); ++i) {
        Material m = file.materials[i];
        if (file.material_images[i])
            m.texture = scene.add_texture(std::make_unique<ImageTexture>(file.material_images[i]));
        if (file.material_normal_images[i])
            m.normal_texture = scene.add_texture(std::make_unique<ImageTexture>(file.material_normal_images[i]));
        result.push_back(scene.add_material(std::move(m)));
    }
    return result;
}

}  // namespace

MeshData load_mesh_data(const std::filesystem::path& path) {
    const MeshFile file = read_mesh_file(path, ReadMode::Strict);
    MeshData data;
    for (const auto& mesh : file.meshes) {
        if (!mesh) continue;  // points or lines only
        const auto base = static_cast<uint32_t>(data.positions.size());
        const MeshData& part = mesh->data();
        data.positions.insert(data.positions.end(), part.positions.begin(), part.positions.end());
        for (const uint32_t index : part.indices) data.indices.push_back(base + index);
    }
    if (data.indices.empty()) throw SceneError(path.string() + ": the file has no triangles (expected at least one)");
    return data;
}

MeshImportResult import_mesh_file(Scene& scene, const std::filesystem::path& path, const Transform& world_from_file,
                                  std::optional<uint32_t> override_material, MeshCache& files) {
    if (override_material && *override_material >= scene.materials().size())
        throw SceneError(path.string() + ": override material " + std::to_string(*override_material) +
                         " does not exist (the scene has " + std::to_string(scene.materials().size()) + ")");
    const std::filesystem::path key = files.canonical(path);
    MeshImportResult result;
    ImportNotes notes;
    MeshCache::Entry* entry = files.find(key);
    result.reused = entry != nullptr;
    // A glTF document, read at most once per call: for the geometry of a file not cached
    // yet, and for its materials on the first placement that uses them. The cache does not
    // keep it, since its buffers hold the whole file.
    std::optional<gltf::Document> doc;
    auto document = [&]() -> const gltf::Document& {
        if (!doc) doc = gltf::read_document(path);
        return *doc;
    };
    // Strong references for this call: the file's meshes live in the scene once placed.
    std::vector<std::shared_ptr<TriangleMesh>> meshes;
    if (entry) {
        for (const auto& weak : entry->meshes) meshes.push_back(weak.lock());
    } else {
        auto fresh = std::make_unique<MeshCache::Entry>();
        fresh->is_gltf = has_gltf_extension(path);
        fresh->file = fresh->is_gltf ? read_gltf_geometry(document()) : read_mesh_file(path, ReadMode::Lenient);
        result.warnings = fresh->file.warnings;
        for (std::string& line : animation_warnings(path, fresh->file)) result.warnings.push_back(std::move(line));
        meshes = std::move(fresh->file.meshes);
        fresh->file.meshes.clear();
        fresh->meshes.assign(meshes.begin(), meshes.end());
        entry = &files.insert(key, std::move(fresh));
    }
    result.declared_up = entry->file.declared_up;
    if (!override_material && !entry->scene_materials)
        entry->scene_materials =
            add_file_materials(scene, entry->file, entry->is_gltf ? &document() : nullptr, meshes, notes);

    auto material = [&](uint32_t mesh) {
        if (override_material) return *override_material;
        const uint32_t file_material = entry->file.mesh_materials[mesh];
        const auto& table = *entry->scene_materials;
        return file_material < table.size() ? table[file_material] : table.empty() ? 0 : table.back();
    };
    const PlacedMeshes placed = place_meshes(scene, entry->file.placements, meshes, world_from_file, material, notes);
    for (const std::string& line : notes.ignored_lines())
        result.warnings.push_back(path.string() + ": ignored " + line);
    result.objects = placed.objects;
    result.triangles = placed.instanced_triangles;
    return result;
}

LoadedScene load_mesh_scene(const std::filesystem::path& path, std::optional<UpAxis> up) {
    LoadedScene loaded;
    MeshCache cache;
    MeshImportResult result = import_mesh_file(loaded.scene, path, Transform(), std::nullopt, cache);
    loaded.warnings = std::move(result.warnings);
    loaded.settings.width = 640;
    loaded.settings.height = 480;
    loaded.scene.camera = framing_camera(loaded.scene.world_bounds(), 640.0f / 480.0f, path,
                                         up.value_or(result.declared_up.value_or(UpAxis::Y)));
    add_default_lighting(loaded.scene);
    return loaded;
}

}  // namespace glint
