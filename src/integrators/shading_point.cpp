#include "glint/integrators/shading_point.h"

#include "glint/scene/render_scene.h"

namespace glint {

Material blended_material(const RenderScene& scene, const SurfaceInteraction& si) {
    const auto& w = si.material_weights;
    return blend(scene.material(si.materials[0]), scene.material(si.materials[1]), scene.material(si.materials[2]),
                 w[0], w[1], w[2]);
}

}  // namespace glint
