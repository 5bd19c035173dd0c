#pragma once
/// \file The render settings a caller can override over a scene's (width, samples,
/// integrator, ...), each checked against the limits scene files have: the command line's
/// options and the Python module's keywords go through the same checks and messages.

#include "glint/integrators/render_settings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct RenderOverrides {
    // Numbers are read signed and wide, then checked against the limits scene files have,
    // so that "-4" or "100000" gets a message in words rather than a conversion error.
    std::optional<int64_t> width, height, spp, depth, threads, seed, light_samples, glossy_samples;
    std::optional<std::string> filter, integrator, mis, aov, crop;
    std::optional<double> filter_radius, adaptive_threshold;
    bool adaptive = false;
};

/// How a setting is named in messages: "--light-samples" on the command line,
/// "light_samples" as a keyword argument (Python).
enum class OptionSpelling { CommandLine, Keyword };

/// `name` ("light-samples") as `spelling` writes it.
[[nodiscard]] std::string option_name(std::string_view name, OptionSpelling spelling);

/// Apply the overrides given to `settings`. Throws std::invalid_argument "--spp: expected
/// ...; got ..." (named as `spelling` says) for a value outside what a scene file accepts,
/// or a filter, integrator or heuristic Glint does not have.
void apply_overrides(const RenderOverrides& overrides, RenderSettings& settings,
                     OptionSpelling spelling = OptionSpelling::CommandLine);

/// A crop region as given, "X0,Y0,X1,Y1": pixels (integers) or, when any number has a
/// decimal point, fractions of the image's width and height from 0 to 1 (pbrt's
/// --cropwindow).
struct CropRequest {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool fractions = false;
};

/// `text` as a CropRequest; throws std::invalid_argument naming the setting `name` ("--crop")
/// unless X0 < X1 and Y0 < Y1, all non-negative, and fractions at most 1.
[[nodiscard]] CropRequest parse_crop(std::string_view text, std::string_view name = "--crop");

/// The pixels `crop` covers in a width × height image: pixels as given, fractions f as
/// ceil(f · side) (pbrt's rule, so that crops of 0–0.5 and 0.5–1 tile the image). Throws
/// std::invalid_argument for a region that reaches past the image or covers no pixel.
[[nodiscard]] PixelRect crop_pixels(const CropRequest& crop, uint32_t width, uint32_t height,
                                    std::string_view name = "--crop");

/// "albedo,depth" as AOVs, each once; throws std::invalid_argument for an unknown name,
/// naming the setting `name` (already spelt: "--aov").
[[nodiscard]] std::vector<Aov> parse_aov_list(std::string_view list, std::string_view name = "--aov");

/// "`name`: expected ...; got `value`" unless `value` lies in [lo, hi].
uint32_t in_range(std::string_view name, int64_t value, int64_t lo, int64_t hi, std::string_view expected = {});

}  // namespace glint
