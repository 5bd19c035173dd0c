#pragma once
/// \file What an asset file that is rendered as a whole scene gets when it lacks a camera
/// or lights (docs/assets.md, "Defaults").

#include "glint/io/scene_file.h"
#include "glint/scene/scene.h"

#include <filesystem>

namespace glint {

/// World bounds of every object, computed from shape bounds (valid before prepare()).
[[nodiscard]] Bounds3 object_bounds(const Scene& scene);

/// A 40° perspective camera that sees all of `bounds` (a sphere around it fits the smaller
/// field of view for images of `aspect` = width/height), looking along -z from slightly above.
[[nodiscard]] Camera framing_camera(const Bounds3& bounds, float aspect);

/// The default lighting: a key light (directional, irradiance 1 in Glint units, from the
/// camera's upper left) plus a uniform grey environment of radiance kDefaultSky that is both
/// the background and the ambient light. Uses scene.camera, so set the camera first.
void add_default_lighting(Scene& scene);

inline constexpr float kDefaultSky = 0.25f;

/// A bare mesh file (PLY, OBJ, STL, FBX...) as a scene: its meshes and materials, a framing
/// camera and the default lighting, 640×480. Throws SceneError.
[[nodiscard]] LoadedScene load_mesh_scene(const std::filesystem::path& path);

}  // namespace glint
