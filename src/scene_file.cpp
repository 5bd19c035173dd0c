#include "glint/scene_file.h"

#include "glint/assets/mesh_loader.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "glint/util/file_extension.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace glint {

namespace {

/// Mesh formats rendered as a scene of their own (framing camera, default lighting).
constexpr std::array<std::string_view, 7> kMeshExtensions = {".obj", ".ply", ".stl", ".fbx", ".dae", ".off", ".3ds"};

}  // namespace

SceneFile load_scene_file(const std::filesystem::path& path, const SceneFileOptions& options) {
    const std::string ext = lower_case_extension(path);
    SceneFile file;
    if (ext == ".gltf" || ext == ".glb") {
        GltfScene gltf = load_gltf_scene(path, GltfOptions{options.camera, options.shutter, options.up.value_or(UpAxis::Y)});
        file.loaded = std::move(gltf.loaded);
        file.default_lighting = gltf.report.default_lighting;
        file.gltf = std::move(gltf.report);
        return file;
    }
    if (!options.camera.empty())
        throw SceneError(path.string() + ": a camera was named (" + options.camera +
                         "), but only glTF files have cameras to choose from");
    if (ext == ".toml") {
        if (options.up)
            throw SceneError(path.string() + ": an up axis was given (--up), but a TOML scene places its own camera");
        file.loaded = load_toml_scene(path);
    } else if (std::find(kMeshExtensions.begin(), kMeshExtensions.end(), ext) != kMeshExtensions.end()) {
        file.loaded = load_mesh_scene(path, options.up);
        file.default_lighting = true;
    } else {
        throw SceneError(path.string() + ": unknown scene format '" + ext +
                         "' (expected .toml, .gltf, .glb or a mesh file: .obj, .ply, .stl, .fbx, .dae, .off, .3ds)");
    }
    return file;
}

}  // namespace glint
