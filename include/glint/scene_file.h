#pragma once
/// \file Loading a scene from a file: the one place that dispatches on the extension
/// (the command line and the tests come through here).

#include "glint/assets/gltf_scene_loader.h"
#include "glint/diagnostics.h"
#include "glint/scene/loaded_scene.h"

#include <filesystem>
#include <optional>
#include <string>

namespace glint {

struct SceneFileOptions {
    /// glTF camera to render through: a name or an index in the file's "cameras" array
    /// (empty: the first placed camera). Naming one for a file that is not glTF is an error.
    std::string camera;
    /// The shutter the scene is rendered with (--time, --shutter): glTF files pose their
    /// animated nodes over it (GltfOptions::shutter); other formats ignore it.
    std::optional<Shutter> shutter = std::nullopt;
    /// The up axis for the automatic camera of a mesh or glTF file (--up); +y when unset.
    /// Naming one for a TOML scene, which places its own camera, is an error.
    std::optional<UpAxis> up = std::nullopt;
};

/// A loaded scene file and what its loader found out about it.
struct SceneFile {
    LoadedScene loaded;
    /// For glTF files: what the loader mapped and ignored.
    std::optional<GltfReport> gltf;
    /// The scene is lit by the asset default lighting (the file has no lights).
    bool default_lighting = false;
};

/// Load by extension (case-insensitive): .toml (Glint's own format, docs/scene-format.md),
/// .gltf/.glb (a whole glTF 2.0 scene, docs/assets.md) or a mesh file (.obj, .ply, .stl,
/// .fbx...: framed by an automatic camera under the default lighting). Throws SceneError.
[[nodiscard]] SceneFile load_scene_file(const std::filesystem::path& path, const SceneFileOptions& options = {});

}  // namespace glint
