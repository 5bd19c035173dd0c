#pragma once
/// \file HDR environment maps as the scene background (seen by camera, reflection and
/// refraction rays that leave the scene).

#include "glint/scene/background.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace glint {

struct EnvironmentOptions {
    /// Layout of the image; unset = guess from its shape (2:1 equirectangular, 1:1 sphere map).
    std::optional<BackgroundKind> kind;
    /// Turns the map about +y, counter-clockwise seen from above.
    float rotation_degrees = 0.0f;
    /// Multiplies the map's radiance.
    float intensity = 1.0f;
};

/// "equirect"/"equirectangular"/"latlong" or "spheremap"/"mirrorball"/"probe"; nullopt otherwise.
[[nodiscard]] std::optional<BackgroundKind> parse_environment_kind(std::string_view name);

/// Read an environment image (HDR, EXR, or an 8-bit image decoded from sRGB) and make it
/// the background. Throws ImageError naming the file when it cannot be read, and
/// std::invalid_argument when the layout cannot be guessed or the intensity is negative.
[[nodiscard]] Background load_environment(const std::filesystem::path& path, const EnvironmentOptions& options = {});

/// Mean radiance of the background over all directions (1024 evenly spread samples):
/// the ambient light an environment stands for in the Whitted model.
[[nodiscard]] Color average_radiance(const Background& background);

}  // namespace glint
