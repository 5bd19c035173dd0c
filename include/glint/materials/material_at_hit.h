#pragma once
/// \file A material's values at one hit, where its textures make them vary. The Bsdf, the
/// Whitted ambient term and the albedo AOV take kd, ka, kr and the roughness from here, so
/// that a texture driving any of them reaches both integrators through one function.

#include "glint/geometry/hit.h"
#include "glint/materials/material.h"
#include "glint/materials/texture.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

namespace glint {

struct MaterialAtHit {
    /// kd·tex: the Lambertian reflectance.
    Color diffuse;
    /// ka·tex: the reflectance of the ambient light.
    Color ambient;
    /// kr: the mirror's weight, or its Schlick F0 for a `fresnel_mirror`.
    Color reflectivity;
    /// Microfacet roughness in [0, 1]; 0 keeps the delta mirror and glass.
    float roughness = 0.0f;
};

/// The values of a material with a metallic_roughness_texture where `q` lands, where its base
/// colour texture (times the vertex colour) is `base_texture`. Out of line: only such
/// materials pay for it. `base_texture` by value, in registers: taken by reference, it made
/// GCC keep every hit's base colour in memory, where material_at_hit() read it back wider
/// than it had been written, a stall of every untextured hit (docs/performance.md,
/// "Store-forwarding stalls").
[[nodiscard]] MaterialAtHit metallic_roughness_at(const Material& m, Color base_texture, const TextureQuery& q);

/// `m` where a lookup `q` lands, on a mesh whose interpolated vertex colour there is
/// `vertex_color`: without a metallic-roughness texture, kd and ka times the texture colour
/// and the vertex colour (they multiply the base colour, as glTF's COLOR_0 does and as
/// Blender's and MeshLab's viewers show PLY colours), kr and the roughness as they are.
/// Inline: it runs at every hit.
[[nodiscard]] inline MaterialAtHit material_at_hit(const Material& m, const TextureQuery& q,
                                                   const Color& vertex_color = Color(1.0f)) {
    // A fully transparent material has no diffuse lobe for the texture to tint: skip the lookup.
    const Color base = m.transparency >= 1.0f ? Color(1.0f) : m.texture ? m.texture->evaluate(q) * vertex_color
                                                                        : vertex_color;
    if (m.metallic_roughness_texture) return metallic_roughness_at(m, base, q);
    return {m.diffuse * base, m.ambient * base, m.reflectivity, m.roughness};
}

/// `m` at a hit: its texture coordinates, the footprint the integrator set and its vertex colour.
[[nodiscard]] inline MaterialAtHit material_at_hit(const Material& m, const SurfaceInteraction& si) {
    return material_at_hit(m, TextureQuery{si.uv, si.p, si.uv_footprint}, si.vertex_color);
}

/// `m` at texture coordinates `uv` (object-space point `p`), looked up at a point.
[[nodiscard]] inline MaterialAtHit material_at_hit(const Material& m, const Vec2& uv, const Vec3& p) {
    return material_at_hit(m, TextureQuery{uv, p, 0.0f});
}

}  // namespace glint
