#pragma once
/// \file Tangent-space normal mapping (Cignoni et al. 1998; Cohen et al. 1998; glTF 2.0
/// §3.9.3 material.normalTexture): the shading normal bent by a texture of normals given in
/// the surface's tangent frame.

#include "glint/geometry/hit.h"
#include "glint/materials/material.h"

namespace glint {

/// The shading normal of `si` bent by `m`'s normal map: the texel (filtered over the hit's
/// footprint) is decoded as n = 2·rgb − 1 with x and y scaled by `normal_scale`, then taken
/// from the frame (t, b, n_s): t is the mesh's vertex tangent, or ∂p/∂u, made perpendicular to
/// the interpolated shading normal n_s; b = sign·(n_s × t), the image's "up" (the vertex
/// tangent's sign, or the side −∂p/∂v lies on). The result is unit and on the geometric
/// normal's side (a map tilting past the true surface is clamped to just above it, so no
/// shading point looks out from under its own surface). Without a map, or without a tangent
/// frame (no uv map), the shading normal as it is.
[[nodiscard]] Vec3 normal_mapped(const Material& m, const SurfaceInteraction& si);

/// Replace the shading normal of `si` by normal_mapped when `m` has a normal map; the
/// integrators call it once they know the material of a hit. Inline: most materials have none.
inline void apply_normal_map(SurfaceInteraction& si, const Material& m) {
    if (m.normal_texture) si.shading_normal = normal_mapped(m, si);
}

}  // namespace glint
