#include "glint/scene/asset_defaults.h"

#include "glint/math/constants.h"

#include <cmath>

namespace glint {

Camera framing_camera(const Bounds3& bounds, float aspect) {
    const Vec3 center = bounds.empty() ? Vec3(0.0f) : bounds.center();
    const float radius = bounds.empty() ? 1.0f : std::max(0.5f * length(bounds.diagonal()), 1e-6f);
    constexpr float vertical_fov = 40.0f;
    // The sphere must fit the narrower of the two fields of view.
    const float half_vertical = radians(vertical_fov) * 0.5f;
    const float half_horizontal = std::atan(std::tan(half_vertical) * aspect);
    const float half = std::min(half_vertical, half_horizontal);
    const float distance = 1.05f * radius / std::sin(half);
    const Vec3 eye = center + normalize(Vec3(0.0f, 0.35f, 1.0f)) * distance;
    return Camera::perspective(eye, center, Vec3(0.0f, 1.0f, 0.0f), vertical_fov);
}

void add_default_lighting(Scene& scene) {
    const Camera& c = scene.camera;
    // Travelling forward, down and to the right: the light comes from the camera's upper left.
    const Vec3 travel = normalize(c.forward() + c.right() * 0.5f - c.up() * 0.7f);
    scene.add_light(std::make_unique<DirectionalLight>(travel, Color(kDefaultKeyLight)));
    scene.background = Background::constant(Color(kDefaultSky));
    scene.ambient_light = Color(kDefaultSky);
}

}  // namespace glint
