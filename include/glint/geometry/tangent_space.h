#pragma once
/// \file Per-vertex tangent frames for normal maps: the direction of +u on the surface and the
/// handedness that says where +v of the normal map (its green channel, "up" in the image)
/// points, in the way of MikkTSpace (Mikkelsen 2008), which glTF asks for when a file has no
/// TANGENT attribute.

#include "glint/math/vec3.h"

#include <vector>

namespace glint {

struct MeshData;

/// A vertex's tangent: unit, perpendicular to the vertex normal, along +u; the bitangent, the
/// direction the normal map's +y (green) means, is sign·(normal × direction). With Glint's
/// texture coordinates (v = 0 the top row of the image, as glTF's) that is the direction of
/// decreasing v, "up" in the image, as glTF's tangent w defines it.
struct Tangent {
    Vec3 direction;
    float sign = 1.0f;
};

/// The tangents of a mesh with normals and texture coordinates (empty otherwise): each
/// triangle's ∂p/∂u and −∂p/∂v, summed at its corners weighted by the corner's angle (as
/// MikkTSpace weighs them), then made perpendicular to the vertex normal (Gram-Schmidt);
/// the sign is that of the summed −∂p/∂v against normal × tangent. A vertex whose triangles
/// have no uv map gets a perpendicular of its normal. Vertices that share an index share a
/// frame: seams where the uvs differ already have their own vertices (glTF, OBJ after
/// import), which is where MikkTSpace would split them.
[[nodiscard]] std::vector<Tangent> compute_tangents(const MeshData& data);

}  // namespace glint
