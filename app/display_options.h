#pragma once
// --exposure and --tonemap: how `glint render` and `glint view` turn radiance into a
// display-referred picture, over what the scene file asks for.

#include "glint/image/display_transform.h"

#include <CLI/CLI.hpp>

#include <optional>

namespace glint::app {

/// Add --exposure STOPS|auto and --tonemap CURVE to `command`; a bad value is a parse error.
void add_display_options(CLI::App* command, std::optional<glint::Exposure>& exposure,
                         std::optional<glint::ToneCurve>& tone_curve);

/// The scene file's display transform with the options given on the command line.
[[nodiscard]] glint::DisplayTransform with_display_options(glint::DisplayTransform from_file,
                                                           const std::optional<glint::Exposure>& exposure,
                                                           const std::optional<glint::ToneCurve>& tone_curve);

}  // namespace glint::app
