#pragma once
/// \file What an asset file that is rendered as a whole scene gets when it lacks a camera
/// or lights (docs/assets.md, "Defaults").

#include "glint/scene/scene.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace glint {

/// Coordinates an automatic camera may take: beyond, squared lengths overflow float.
inline constexpr double kMaxFramedCoordinate = 1e18;

/// The axis that points up in an asset: +y in glTF and most tools, +z in CAD, scans (the
/// Stanford Lucy) and Blender's own coordinates.
enum class UpAxis { X, Y, Z };

/// "x", "y" or "z"; nullopt otherwise.
[[nodiscard]] std::optional<UpAxis> parse_up_axis(std::string_view name);

/// A 40° perspective camera that sees all of `bounds` (a sphere around it fits the smaller
/// field of view for images of `aspect` = width/height), from the front and slightly above
/// for `up`: looking along -z for +y up (and +x up), along +y for +z up (Blender's front view).
/// Throws SceneError naming `file` (the asset the bounds come from) when that camera would
/// stand beyond ±kMaxFramedCoordinate: absurdly large or distant geometry.
[[nodiscard]] Camera framing_camera(const Bounds3& bounds, float aspect, const std::filesystem::path& file,
                                    UpAxis up = UpAxis::Y);

/// Irradiance (Glint units) of the default key light and radiance of the default grey sky:
/// a white Lambertian surface facing the key light shows 0.75 + 0.2 = 0.95, just below white.
inline constexpr float kDefaultKeyLight = 0.75f;
inline constexpr float kDefaultSky = 0.2f;

/// The default lighting: a directional key light of irradiance kDefaultKeyLight from the
/// camera's upper left, plus a uniform grey environment of radiance kDefaultSky that is both
/// the background and the ambient light. Uses scene.camera, so set the camera first.
void add_default_lighting(Scene& scene);

}  // namespace glint
