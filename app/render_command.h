#pragma once
// `glint render`: its options, checked against the limits scene files have, and the render
// itself: load, prepare, render (interruptible, resumable), write.

#include "render_overrides.h"
#include "scene_source.h"

#include "glint/image/display_transform.h"

#include <cstdint>
#include <optional>
#include <string>

namespace glint::app {

struct RenderOptions {
    std::string scene_path;
    SceneOptions scene;
    std::string output;
    RenderOverrides overrides;
    /// --exposure and --tonemap; unset: what the scene file asks for (LoadedScene::display).
    std::optional<glint::Exposure> exposure;
    std::optional<glint::ToneCurve> tone_curve;
    bool quiet = false;
    /// Continue from the checkpoint beside the output (`<output>.checkpoint`).
    bool resume = false;
    /// Save a checkpoint this often while rendering (seconds; none when unset).
    std::optional<double> checkpoint_every;
    /// Stream the image as it renders to a display server such as tev ("HOST:PORT").
    std::optional<std::string> display_server;
};

/// Run `glint render`; returns the exit status (0, or 128 + the signal that interrupted it).
/// Throws on every error, with a message for the user.
int run_render(const RenderOptions& options);

}  // namespace glint::app
