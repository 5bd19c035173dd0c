#pragma once
// Loading the scene a command names: scene files, glTF with a chosen camera, and the
// environment flags shared by `glint render` and `glint info`.

#include "glint/scene_file.h"

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
    /// --aperture and --focus: the camera's lens radius and focus distance, world units.
    std::optional<float> aperture, focus;
    /// --shutter OPEN,CLOSE and --time T (an instant, [T, T]), in scene time.
    std::optional<std::string> shutter;
    std::optional<float> time;
    /// The shutter of one frame of `glint render --frames` (in place of the two above).
    std::optional<Shutter> frame_shutter;
    /// --up x|y|z: the up axis of a mesh or glTF file's automatic camera.
    std::string up;
};

/// What `render` and `info` load: a scene file, or the built-in scene.
using SceneSource = SceneFile;

/// Load `path` (the built-in spheres scene when empty) and apply the camera, lens and
/// environment options. Throws SceneError, ImageError or std::invalid_argument.
[[nodiscard]] SceneSource load_scene(const std::string& path, const SceneOptions& options);

/// Add --camera, --up, --aperture, --focus, --shutter, --time, --env, --env-kind,
/// --env-rotation and --env-intensity to `command`.
void add_scene_options(CLI::App* command, SceneOptions& options);

}  // namespace glint::app
