#pragma once
// The render settings a command line can override (width, samples, integrator, ...),
// shared by `glint render` and `glint explain`, each checked against the limits scene files
// have before anything is loaded.

#include "glint/integrators/render_settings.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::app {

struct RenderOverrides {
    // Numbers are read signed and wide, then checked against the limits scene files have,
    // so that "-4" or "100000" gets a message in words rather than a conversion error.
    std::optional<int64_t> width, height, spp, depth, threads, seed, light_samples, glossy_samples;
    std::optional<std::string> filter, integrator, mis, aov;
    std::optional<double> filter_radius, adaptive_threshold;
    bool adaptive = false;
};

/// Add --width, --height, --spp, --depth, --threads, --seed, --filter, --filter-radius,
/// --integrator, --light-samples, --glossy-samples, --mis, --aov, --adaptive and
/// --adaptive-threshold to `command`.
void add_render_overrides(CLI::App* command, RenderOverrides& overrides);

/// Apply the overrides given to `settings`. Throws std::invalid_argument "--spp: expected
/// ...; got ..." for a value outside what a scene file accepts.
void apply_overrides(const RenderOverrides& overrides, RenderSettings& settings);

/// "albedo,depth" as AOVs, each once; throws std::invalid_argument for an unknown name.
[[nodiscard]] std::vector<Aov> parse_aov_list(std::string_view list);

/// "`name`: expected ...; got `value`" unless `value` lies in [lo, hi].
uint32_t in_range(std::string_view name, int64_t value, int64_t lo, int64_t hi, std::string_view expected = {});

}  // namespace glint::app
