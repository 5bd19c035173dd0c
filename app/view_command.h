#pragma once
// `glint view`: a window that renders the scene progressively, with an orbit camera, and
// explains the pixel clicked. Built when SDL2 and Dear ImGui are installed (libsdl2-dev,
// libimgui-dev), as the program glint-view; otherwise the command says so.

#include "render_overrides.h"
#include "scene_source.h"

#include "glint/image/display_transform.h"

#include <optional>
#include <string>

namespace glint::app {

struct ViewOptions {
    std::string scene_path;
    SceneOptions scene;
    RenderOverrides overrides;
    /// Where `S` saves the accumulated image; default <scene>.png.
    std::string output;
    /// --exposure and --tonemap over the scene's own display transform.
    std::optional<glint::Exposure> exposure;
    std::optional<glint::ToneCurve> tone_curve;
    /// A scripted session (viewer/session_script.h), read from this file.
    std::optional<std::string> script;
    /// Orbit for this many frames, then render to convergence; print frames/s and the time.
    std::optional<int64_t> benchmark;
};

void add_view_options(CLI::App* command, ViewOptions& options);

/// Run `glint view`; returns the exit status. Throws on every error, with a message. `glint`
/// itself replaces its process by `glint-view` with the same arguments (`argc`, `argv`);
/// `glint-view` opens the window.
int run_view(const ViewOptions& options, int argc, char** argv);

}  // namespace glint::app
