#include "glint/integrators/ray_cone.h"

#include "glint/scene/camera.h"

#include <algorithm>

namespace glint {

RayCone camera_ray_cone(const Camera& camera, uint32_t height, uint32_t samples_per_axis) {
    const float share = 1.0f / float(std::clamp(samples_per_axis, 1u, 8u));
    const float pixels = float(std::max(height, 1u));
    if (camera.projection() == Projection::Orthographic) return {camera.view_height() / pixels * share, 0.0f};
    return {0.0f, 2.0f * camera.tan_half_fov() / pixels * share};
}

}  // namespace glint
