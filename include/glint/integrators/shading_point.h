#pragma once
/// \file What every integrator works out at a hit before shading it: the material (blended
/// for per-vertex materials), the normals turned towards the viewer, and the two indices
/// of refraction of the interface from the ray's stack of media.

#include "glint/geometry/hit.h"
#include "glint/integrators/ior_stack.h"
#include "glint/lights/light.h"
#include "glint/materials/bsdf.h"
#include "glint/materials/material.h"
#include "glint/math/offset_ray.h"
#include "glint/math/ray.h"

#include <optional>

namespace glint {

class RenderScene;

struct ShadingPoint {
    /// The material at the hit; a blended copy only for per-vertex materials.
    const Material* material = nullptr;
    std::optional<Material> blended;
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

/// Resolve the material, normals and interface of a hit. Entering or leaving a dielectric is
/// decided by the stack of media: a material the ray is not inside is being entered,
/// whatever the winding of the surface (open or inward-wound glass is glass, not a mirror);
/// only a stack that lost track of an entry leaves the decision to the winding.
[[nodiscard]] ShadingPoint shading_point(const RenderScene& scene, const SurfaceInteraction& si, const Ray& ray,
                                         const IorStack& media);

/// Texture colour multiplying kd at the hit (white without a texture, or for a fully
/// transparent material, whose diffuse and ambient terms have weight 0).
[[nodiscard]] Color diffuse_texture(const Material& m, const SurfaceInteraction& si);

/// The shadow ray from a surface point (geometric normal `ng` on the side the light is) to a
/// light sample: unbounded for directional lights, ending at the light's point for point
/// lights, and ending just off the surface of an area light so that it cannot block itself.
[[nodiscard]] inline Ray shadow_ray(const Vec3& p, const Vec3& ng, const LightSample& ls) {
    const Vec3 origin = offset_ray_origin(p, ng);
    if (ls.is_delta) return Ray(origin, ls.direction, 0.0f, ls.distance);
    const Vec3 target = offset_ray_origin(ls.point, ls.normal);
    const Vec3 d = target - origin;
    const float dist = length(d);
    // Stop a hair short of the offset end point: the light's own surface lies beyond it.
    return Ray(origin, d / dist, 0.0f, dist * (1.0f - 1e-4f));
}

}  // namespace glint
