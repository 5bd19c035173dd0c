#pragma once
/// \file Beer-Lambert absorption inside dielectrics (Material::absorption): what a ray keeps
/// of its radiance over the distance it travels inside the medium its stack says it is in.

#include "glint/integrators/ior_stack.h"
#include "glint/scene/render_scene.h"

#include <cmath>

namespace glint {

/// exp(−σa·distance) for the medium `media` is in, σa its material's absorption; white
/// outside every medium and in clear ones (the common case costs one branch).
[[nodiscard]] inline Color transmittance(const RenderScene& scene, const IorStack& media, float distance) {
    const std::optional<uint32_t> medium = media.current_medium();
    if (!medium) return Color(1.0f);
    const Color& sigma = scene.material(*medium).absorption;
    if (sigma.is_black()) return Color(1.0f);
    return {std::exp(-sigma.r * distance), std::exp(-sigma.g * distance), std::exp(-sigma.b * distance)};
}

}  // namespace glint
