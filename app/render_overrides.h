#pragma once
// The command-line options that override a scene's render settings (width, samples,
// integrator, ...), shared by `glint render`, `glint explain` and `glint view`; the checks
// are the library's (glint/integrators/render_overrides.h).

#include "glint/integrators/render_overrides.h"

#include <CLI/CLI.hpp>

namespace glint::app {

/// Add --width, --height, --spp, --depth, --threads, --seed, --filter, --filter-radius,
/// --integrator, --light-samples, --glossy-samples, --mis, --aov, --adaptive and
/// --adaptive-threshold to `command`.
void add_render_overrides(CLI::App* command, RenderOverrides& overrides);

}  // namespace glint::app
