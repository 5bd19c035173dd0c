#pragma once
/// \file Arbitrary output variables: what a render can write beside the image, as extra
/// channels of the same EXR, named after the OpenEXR and Nuke conventions (layer.channel).
///
/// The first-hit layers describe the surface each camera ray hits first, averaged over the
/// pixel's samples (unweighted by the pixel filter, whose weights may be negative):
///   albedo.R/G/B  the diffuse reflectance kd·texture·(1 − transparency) there (0 for a miss;
///                 as Mitsuba 3's `albedo` AOV, specular lobes excluded)
///   N.X/Y/Z       the world-space shading normal, turned towards the camera (0 for a miss)
///   P.X/Y/Z       the world-space position (0 for a miss)
///   Z             the distance along the camera ray, averaged over the samples that hit;
///                 +inf where none did
/// and the sampling layers describe the estimate:
///   spp           the number of samples the pixel took
///   variance.R/G/B the variance of the pixel's mean radiance, s²/n from its samples' spread

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

enum class Aov : uint8_t { Albedo, Normal, Depth, Position, Spp, Variance };

/// The names `--aov` and `[render] aovs` take, in the order of `Aov`.
[[nodiscard]] std::span<const std::string_view> aov_names();
[[nodiscard]] std::optional<Aov> aov_from_name(std::string_view name);
[[nodiscard]] std::string_view aov_name(Aov aov);
/// The EXR channel names of one AOV ("albedo.R", "albedo.G", "albedo.B"; "Z").
[[nodiscard]] std::vector<std::string> aov_channels(Aov aov);

}  // namespace glint
