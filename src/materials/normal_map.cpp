#include "glint/materials/normal_map.h"

#include <cmath>

namespace glint {

Vec3 normal_mapped(const Material& m, const SurfaceInteraction& si) {
    const Vec3& n = si.shading_normal;
    const bool has_vertex_tangent = dot(si.tangent, si.tangent) > 0.0f;
    const Vec3 along = has_vertex_tangent ? si.tangent : si.dpdu;
    Vec3 t = along - n * dot(n, along);
    const float t_length = length(t);
    if (!(t_length > 0.0f) || !std::isfinite(t_length)) return n;
    t = t / t_length;
    const float sign = has_vertex_tangent ? si.tangent_sign : (dot(cross(n, t), -si.dpdv) < 0.0f ? -1.0f : 1.0f);
    const Vec3 b = cross(n, t) * sign;

    const Color texel = m.normal_texture->evaluate(TextureQuery{si.uv, si.p, si.uv_footprint});
    const Vec3 local((2.0f * texel.r - 1.0f) * m.normal_scale, (2.0f * texel.g - 1.0f) * m.normal_scale,
                     2.0f * texel.b - 1.0f);
    const Vec3 bent = t * local.x + b * local.y + n * local.z;
    const float bent_length = length(bent);
    if (!(bent_length > 0.0f) || !std::isfinite(bent_length)) return n;
    Vec3 mapped = bent / bent_length;
    // Keep it on the true surface's outer side (as face_forward keeps interpolated normals):
    // project a normal that tilts below the surface back to just above it.
    const Vec3& ng = si.geometric_normal;
    const float below = dot(mapped, ng);
    if (below < 1e-3f) mapped = normalize(mapped + ng * (1e-3f - below));
    return mapped;
}

}  // namespace glint
