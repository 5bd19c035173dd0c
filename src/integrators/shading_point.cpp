#include "glint/integrators/shading_point.h"

#include "glint/math/offset_ray.h"
#include "glint/scene/render_scene.h"

#include <cmath>

namespace glint {

ShadingPoint shading_point(const RenderScene& scene, const SurfaceInteraction& si, const Ray& ray, const IorStack& media) {
    ShadingPoint sp;
    sp.medium = si.materials[0];
    if (si.blends_materials) {
        const auto& w = si.material_weights;
        sp.blended = blend(scene.material(si.materials[0]), scene.material(si.materials[1]),
                           scene.material(si.materials[2]), w[0], w[1], w[2]);
        sp.material = &*sp.blended;
    } else {
        sp.material = &scene.material(sp.medium);
    }
    sp.wo = -normalize(ray.direction);
    // Shade on the side the ray arrived from (surfaces are two-sided).
    sp.n = si.front_face ? si.shading_normal : -si.shading_normal;
    sp.ng = si.front_face ? si.geometric_normal : -si.geometric_normal;
    if (sp.material->is_dielectric()) {
        const bool inside = media.contains(sp.medium);
        sp.entering = inside ? false : (media.lost_entries() ? si.front_face : true);
        // Indices on both sides of the interface, from the stack of media (handout §5.4.1).
        sp.media.eta_from = sp.entering ? media.current() : sp.material->ior;
        sp.media.eta_to = sp.entering ? sp.material->ior : media.outside_of(sp.medium);
    }
    return sp;
}

Color diffuse_texture(const Material& m, const SurfaceInteraction& si) {
    // A fully transparent material has no diffuse lobe for the texture to tint: skip the lookup.
    if (!m.texture || m.transparency >= 1.0f) return Color(1.0f);
    return m.texture->evaluate(si.uv, si.p);
}

}  // namespace glint
