#pragma once
/// \file How a render becomes a display-referred picture (PNG, JPEG, 8-bit TIFF): exposure,
/// then a tone curve, then sRGB encoding. EXR, HDR and PFM files never see it.

#include "glint/image/image.h"
#include "glint/image/tone_curve.h"

#include <optional>
#include <string_view>

namespace glint {

/// Middle grey: the display-linear value auto exposure puts the image's key at (18 %
/// reflectance, the photographer's grey card; Reinhard et al. 2002, "Photographic Tone
/// Reproduction for Digital Images", §2).
inline constexpr float kMiddleGrey = 0.18f;

/// Radiance is multiplied by 2^stops before the tone curve; `automatic` chooses the stops
/// from the image when it is written (auto_exposure_stops).
struct Exposure {
    bool automatic = false;
    float stops = 0.0f;

    bool operator==(const Exposure&) const = default;
};

struct DisplayTransform {
    ToneCurve tone_curve = ToneCurve::None;
    Exposure exposure;

    bool operator==(const DisplayTransform&) const = default;
};

/// The exposure, in stops, of a light meter: the image's log-average luminance (Reinhard et
/// al. 2002, eq. 1) becomes middle grey. Only pixels with some light count: a black
/// background says nothing about how the lit part should be exposed. 0 for an image with
/// no light.
[[nodiscard]] float auto_exposure_stops(const Image& image);

/// The stops `exposure` gives `image`: its own, or auto_exposure_stops(image) when automatic.
[[nodiscard]] inline float exposure_stops(const Exposure& exposure, const Image& image) {
    return exposure.automatic ? auto_exposure_stops(image) : exposure.stops;
}

/// "auto" or a finite number of stops; nullopt for anything else.
[[nodiscard]] std::optional<Exposure> parse_exposure(std::string_view text);

}  // namespace glint
