#pragma once
// Loading the scene a command names: scene files, glTF with a chosen camera, and the
// environment flags shared by `glint render` and `glint info`.

#include "glint/io/gltf_scene_loader.h"
#include "glint/io/scene_file.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace glint::app {

/// How to pick the scene's camera and environment; shared by `render` and `info`.
struct SceneOptions {
    std::string camera;
    std::string env;
    std::string env_kind;
    float env_rotation = 0.0f;
    float env_intensity = 1.0f;
};

/// A loaded scene and, for glTF files, what the loader mapped.
struct SceneSource {
    LoadedScene loaded;
    std::optional<GltfReport> gltf;
    /// The scene is lit by the asset default lighting (no lights in the file).
    bool default_lighting = false;
};

/// Load `path` (the built-in spheres scene when empty) and apply the camera and environment
/// options. Throws SceneError, ImageError or std::invalid_argument.
[[nodiscard]] SceneSource load_scene(const std::string& path, const SceneOptions& options);

/// Add --camera, --env, --env-kind, --env-rotation and --env-intensity to `command`.
void add_scene_options(CLI::App* command, SceneOptions& options);

}  // namespace glint::app
