#pragma once
/// \file A pixel's explanation (Integrator::explain) in words: the indented ray tree that
/// `glint explain` prints and the viewer shows, and the JSON of `glint explain --json` (which
/// the Python module's glint.explain returns as dicts).

#include "glint/integrators/ray_tree.h"
#include "glint/integrators/render_settings.h"

#include <string>

namespace glint {

class RenderScene;

[[nodiscard]] std::string explanation_text(const RenderScene& scene, const RenderSettings& settings,
                                           const PixelExplanation& explanation);
[[nodiscard]] std::string explanation_json(const RenderScene& scene, const RenderSettings& settings,
                                           const PixelExplanation& explanation);

}  // namespace glint
