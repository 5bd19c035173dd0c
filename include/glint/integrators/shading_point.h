#pragma once
/// \file What every integrator works out at a hit before shading it: the material (blended
/// for per-vertex materials), the normals turned towards the viewer, and the two indices
/// of refraction of the interface from the ray's stack of media.

#include "glint/geometry/hit.h"
#include "glint/image/aov_film.h"
#include "glint/integrators/ior_stack.h"
#include "glint/lights/light.h"
#include "glint/materials/bsdf.h"
#include "glint/materials/material.h"
#include "glint/materials/material_at_hit.h"
#include "glint/math/offset_ray.h"
#include "glint/math/ray.h"

#include <algorithm>

namespace glint {

class RenderScene;

struct ShadingPoint {
    /// Unit shading and geometric normals on the side the ray came from.
    Vec3 n, ng;
    /// Unit direction back along the ray.
    Vec3 wo;
    /// True if the ray passes into the material's medium here, false if it leaves it.
    bool entering = true;
    Interface media;
    /// The material index whose medium the ray enters or leaves.
    uint32_t medium = 0;
};

/// The hit's unit geometric normal on the side the ray came from (surfaces are two-sided):
/// ShadingPoint::ng, and the side shadow rays leave from.
[[nodiscard]] inline Vec3 facing_geometric_normal(const SurfaceInteraction& si) {
    return si.front_face ? si.geometric_normal : -si.geometric_normal;
}

/// The per-vertex materials of a hit (si.blends_materials) blended by their weights. Kept
/// apart from shading_point: the common hit on one material uses the scene's own
/// `Material` and never constructs one (GCC 12 zero-fills an empty std::optional<Material>,
/// a cost every hit would pay).
[[nodiscard]] Material blended_material(const RenderScene& scene, const SurfaceInteraction& si);

/// Resolve the normals and interface of a hit on material `m` (the scene's material of
/// si.materials[0], or the blended one). Entering or leaving a dielectric is decided by the
/// stack of media: a material the ray is not inside is being entered, whatever the winding
/// of the surface (open or inward-wound glass is glass, not a mirror); only a stack that
/// lost track of an entry leaves the decision to the winding. Inline: every integrator
/// calls it at every hit.
[[nodiscard]] inline ShadingPoint shading_point(const SurfaceInteraction& si, const Material& m, const Ray& ray,
                                                const IorStack& media) {
    ShadingPoint sp;
    sp.medium = si.materials[0];
    sp.wo = -normalize(ray.direction);
    // Shade on the side the ray arrived from (surfaces are two-sided).
    sp.n = si.front_face ? si.shading_normal : -si.shading_normal;
    sp.ng = facing_geometric_normal(si);
    if (m.is_dielectric()) {
        const bool inside = media.contains(sp.medium);
        sp.entering = inside ? false : (media.lost_entries() ? si.front_face : true);
        // Indices on both sides of the interface, from the stack of media (handout §5.4.1).
        sp.media.eta_from = sp.entering ? media.current() : m.ior;
        sp.media.eta_to = sp.entering ? m.ior : media.outside_of(sp.medium);
    }
    return sp;
}

/// A hit's shading before any ray leaves it: where it faces (shading_point), the material's
/// values there and its BSDF. Worked out once, by shade(), or for a packet's first hits
/// before their mirror rays are traced together.
struct HitShading {
    ShadingPoint sp;
    MaterialAtHit at;
    Bsdf bsdf;

    /// Always inlined: called out of line from shade(), as GCC chose, it cost glossy.toml 1.4 %.
    [[gnu::always_inline]] HitShading(const SurfaceInteraction& si, const Material& m, const Ray& ray,
                                      const IorStack& media)
        : sp(shading_point(si, m, ray, media)), at(material_at_hit(m, si)), bsdf(m, at, sp.n, sp.ng, sp.wo, sp.media) {}

    /// Whether the BSDF has a mirror reflection that leaves above the true surface (a
    /// shading normal can bend it below, where it would start inside).
    [[nodiscard]] bool reflects() const {
        const SpecularLobes& specular = bsdf.specular();
        return !specular.reflection.is_black() && dot(specular.reflected, sp.ng) > 0.0f;
    }
    /// The mirror reflection's ray from the hit `si`.
    [[nodiscard]] Ray reflected_ray(const SurfaceInteraction& si) const {
        return Ray(offset_ray_origin(si.p, sp.ng), bsdf.specular().reflected, 0.0f, kInfinity, si.time);
    }
};

/// What the AOVs take from the camera ray's hit (image/aov.h): the diffuse albedo
/// kd·texture·(1 − t) (`at` = material_at_hit of `m` there), the shading normal towards the
/// camera, the position and the distance along the camera ray.
inline void record_first_hit(FirstHit& out, const Ray& camera_ray, const SurfaceInteraction& si, const ShadingPoint& sp,
                             const Material& m, const MaterialAtHit& at) {
    out.hit = true;
    out.albedo = at.diffuse * (1.0f - std::clamp(m.transparency, 0.0f, 1.0f));
    out.normal = sp.n;
    out.position = si.p;
    out.distance = length(si.p - camera_ray.origin);
}

/// The shadow ray from `origin`, a surface point already moved off its surface to the side
/// the light is on (offset_ray_origin), to a light sample: unbounded for directional lights
/// and the environment (lights at infinite distance), ending at the light's point for point
/// lights, and ending just off the surface of an area
/// light so that it cannot block itself. A point lit by several lights offsets once. The
/// ray travels at `time`, the time of the ray that found the point.
[[nodiscard]] inline Ray shadow_ray(const Vec3& origin, const LightSample& ls, float time) {
    if (ls.is_delta || ls.distance == kInfinity) return Ray(origin, ls.direction, 0.0f, ls.distance, time);
    const Vec3 target = offset_ray_origin(ls.point, ls.normal);
    const Vec3 d = target - origin;
    const float dist = length(d);
    // Stop a hair short of the offset end point: the light's own surface lies beyond it.
    return Ray(origin, d / dist, 0.0f, dist * (1.0f - 1e-4f), time);
}

/// The shadow ray from surface point `p` (geometric normal `ng` on the side the light is) to
/// a light sample, at `time`.
[[nodiscard]] inline Ray shadow_ray(const Vec3& p, const Vec3& ng, const LightSample& ls, float time) {
    return shadow_ray(offset_ray_origin(p, ng), ls, time);
}

}  // namespace glint
