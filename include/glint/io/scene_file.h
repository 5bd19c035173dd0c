#pragma once
/// \file Loading a scene from a file: the entry point loaders share.

#include "glint/integrators/render_settings.h"
#include "glint/scene/scene.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace glint {

/// A problem in an input file. what() reads `file:line:column: what is wrong and what was
/// expected` (line and column where the format knows them).
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What a loader produces: the scene, the render settings the file asks for, and warnings
/// about what it could not map (the render goes on without it).
struct LoadedScene {
    Scene scene;
    RenderSettings settings;
    std::vector<std::string> warnings;
};

/// Load by extension: .toml (Glint's own format, docs/scene-format.md), .gltf/.glb (a whole
/// glTF 2.0 scene, docs/assets.md) or a mesh file (.obj, .ply, .stl, .fbx...: framed by an
/// automatic camera under the default lighting). Throws SceneError.
[[nodiscard]] LoadedScene load_scene_file(const std::filesystem::path& path);

}  // namespace glint
