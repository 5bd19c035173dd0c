#pragma once
// `glint explain`: why a pixel has its colour. Renders one pixel as `glint render` would,
// records the rays of its samples and prints them as an indented tree or as JSON.

#include "render_overrides.h"
#include "scene_source.h"

#include <cstdint>
#include <optional>
#include <string>

namespace glint::app {

struct ExplainOptions {
    std::string scene_path;
    SceneOptions scene;
    RenderOverrides overrides;
    /// "X,Y": column and row from the top-left, as an image viewer shows them.
    std::string pixel;
    /// One sample's rays only (0 to spp − 1); every sample's when unset.
    std::optional<int64_t> sample;
    bool json = false;
};

/// Add the `explain` subcommand's options to `command`.
void add_explain_options(CLI::App* command, ExplainOptions& options);

/// Run `glint explain`; returns the exit status. Throws on every error, with a message for
/// the user.
int run_explain(const ExplainOptions& options);

}  // namespace glint::app
