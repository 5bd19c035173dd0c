#pragma once
/// \file The built-in scene `glint render` shows when given no scene file.

#include "glint/scene/loaded_scene.h"
#include "glint/scene/scene.h"

namespace glint {

/// The seminar's spheres scene (its `buildSpheres`): three materials on a grid of spheres
/// over a floor, two point lights, camera at (22, 24, 26) looking at (0, 2, 0), up +y,
/// 52° vertical field of view. With `refraction_variant` the seminar's refraction slide:
/// no mirror reflection, and material 1 is glass (transparency 0.9, index 1.5).
[[nodiscard]] Scene make_spheres_scene(bool refraction_variant = false);

/// What `glint render` with no scene file renders (and the Python module's
/// glint.default_scene()): the spheres scene at 2×2 samples per pixel, the other settings
/// at their defaults.
[[nodiscard]] LoadedScene make_default_scene();

}  // namespace glint
