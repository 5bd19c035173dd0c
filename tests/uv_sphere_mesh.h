#pragma once
// A latitude-longitude sphere of radius 1 around the origin as a triangle mesh, with unit
// normals and texture coordinates (so that the mesh has tangents too), for tests that need a
// curved mesh with every per-vertex attribute a shading point reads.

#include "glint/geometry/triangle_mesh.h"
#include "glint/math/constants.h"

#include <cmath>
#include <cstdint>

namespace glint_test {

/// `rings` from pole to pole, `segments` around; vertex (r, s) has uv (s/segments, r/rings).
inline glint::MeshData uv_sphere_mesh(int rings, int segments) {
    using glint::Vec2;
    using glint::Vec3;
    glint::MeshData m;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = glint::kPi * float(r) / float(rings),
                        phi = 2.0f * glint::kPi * float(s) / float(segments);
            const Vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            m.positions.push_back(p);
            m.normals.push_back(p);
            m.uvs.push_back(Vec2(float(s) / float(segments), float(r) / float(rings)));
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const auto a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments) + 1;
            m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    return m;
}

}  // namespace glint_test
