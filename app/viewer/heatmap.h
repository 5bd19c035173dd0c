#pragma once
// Heatmaps of what pixels cost (glint/integrators/cost_map.h) as the viewer shows them: the
// viridis colour scale (perceptually uniform, readable in grey and by most colour-blind
// viewers; van der Walt and Smith, matplotlib 2015) from 0 to the image's maximum, and its
// legend.

#include "glint/integrators/cost_map.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace glint::app {

/// The view names of `show` in a session script and of the panel: "image" (none), "nodes",
/// "primitives", "shadow", "depth".
[[nodiscard]] std::optional<CostKind> cost_kind_from_view_name(std::string_view name);

/// Viridis at v in [0, 1], as 8-bit sRGB.
void viridis(float v, uint8_t rgb[3]);

/// RGBA8 pixels of `kind` over `map`, 0 and the maximum at the ends of the scale.
[[nodiscard]] std::vector<uint8_t> heatmap_rgba(const CostMap& map, CostKind kind);

/// The colour bar with its end values, in the current ImGui window.
void draw_heatmap_legend(CostKind kind, uint32_t max);

}  // namespace glint::app
