#pragma once
/// \file HDR environment maps as the scene background (seen by camera, reflection and
/// refraction rays that leave the scene).

#include "glint/scene/background.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace glint {

struct EnvironmentOptions {
    /// Layout of the image; unset = guess from its shape (2:1 equirectangular, 1:1 sphere
    /// map; an angular map is square too, so it must be named).
    std::optional<BackgroundKind> kind;
    /// Turns the map about +y, counter-clockwise seen from above.
    float rotation_degrees = 0.0f;
    /// Multiplies the map's radiance.
    float intensity = 1.0f;
};

/// "equirect"/"equirectangular"/"latlong", "spheremap"/"mirrorball"/"probe" or
/// "angmap"/"angular"; nullopt otherwise.
[[nodiscard]] std::optional<BackgroundKind> parse_environment_kind(std::string_view name);

/// What is wrong with a width × height image as a map of layout `kind` (an equirectangular
/// map is 2:1, a sphere or angular map square), as the shape expected and the shape
/// found; nullopt when it fits.
[[nodiscard]] std::optional<std::string> environment_shape_problem(BackgroundKind kind, int width, int height);

/// Read an environment image (HDR, EXR, or an 8-bit image decoded from sRGB) and make it
/// the background. Throws ImageError naming the file when it cannot be read, and
/// std::invalid_argument naming the file when the layout cannot be guessed, the image does
/// not have the given layout's shape, or the intensity is negative.
[[nodiscard]] Background load_environment(const std::filesystem::path& path, const EnvironmentOptions& options = {});

/// Mean radiance of the background over all directions (1024 evenly spread samples):
/// the ambient light an environment stands for in the Whitted model.
[[nodiscard]] Color average_radiance(const Background& background);

}  // namespace glint
