#include "glint/io/scene_file.h"

#include "glint/io/asset_defaults.h"
#include "glint/io/gltf_scene_loader.h"
#include "glint/io/toml_scene_loader.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace glint {

namespace {

/// Mesh formats rendered as a scene of their own (framing camera, default lighting).
constexpr std::array<const char*, 7> kMeshExtensions = {".obj", ".ply", ".stl", ".fbx", ".dae", ".off", ".3ds"};

}  // namespace

LoadedScene load_scene_file(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".toml") return load_toml_scene(path);
    if (ext == ".gltf" || ext == ".glb") return std::move(load_gltf_scene(path).loaded);
    if (std::find(kMeshExtensions.begin(), kMeshExtensions.end(), ext) != kMeshExtensions.end())
        return load_mesh_scene(path);
    throw SceneError(path.string() + ": unknown scene format '" + ext +
                     "' (expected .toml, .gltf, .glb or a mesh file: .obj, .ply, .stl, .fbx, .dae, .off, .3ds)");
}

}  // namespace glint
