#pragma once
/// \file A material's values at one hit, where its textures make them vary. The Bsdf, the
/// Whitted ambient term and the albedo AOV take kd, ka, kr and the roughness from here, so
/// that a texture driving any of them reaches both integrators through one function.

#include "glint/materials/material.h"
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

/// The values of a material with a metallic_roughness_texture at `uv`, where its base colour
/// texture is `base_texture`. Out of line: only such materials pay for it.
[[nodiscard]] MaterialAtHit metallic_roughness_at(const Material& m, const Color& base_texture, const Vec2& uv,
                                                  const Vec3& p);

/// `m` at texture coordinates `uv` (object-space point `p` for solid textures): without a
/// metallic-roughness texture, kd and ka times the texture colour, kr and the roughness as
/// they are. Inline: it runs at every hit.
[[nodiscard]] inline MaterialAtHit material_at_hit(const Material& m, const Vec2& uv, const Vec3& p) {
    // A fully transparent material has no diffuse lobe for the texture to tint: skip the lookup.
    const Color texture = !m.texture || m.transparency >= 1.0f ? Color(1.0f) : m.texture->evaluate(uv, p);
    if (m.metallic_roughness_texture) return metallic_roughness_at(m, texture, uv, p);
    return {m.diffuse * texture, m.ambient * texture, m.reflectivity, m.roughness};
}

}  // namespace glint
