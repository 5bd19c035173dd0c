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

class MpiSession;

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
    /// --frames: render these frames, `output` naming them with a run of '#' (frame_sequence.h).
    std::optional<std::string> frames;
    /// Frames per second: frame f shows scene time f / fps.
    double fps = 24.0;
    /// The fraction of a frame the shutter is open from the frame's time (0: sharp frames).
    double motion_blur = 0.0;
    /// Render frames whose image is already there again.
    bool overwrite = false;
    /// The processes rendering this image together (mpirun); null or of one: this one alone.
    const MpiSession* mpi = nullptr;
};

/// Run `glint render`: one image, or with `frames` an animation. Returns the exit status (0,
/// or 128 + the signal that interrupted it). Throws on every error, with a message for the
/// user.
int run_render(const RenderOptions& options);

/// Render the one image `options.output` (its `frames` unset); run_render's status.
int render_image(const RenderOptions& options);

}  // namespace glint::app
