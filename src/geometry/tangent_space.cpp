#include "glint/geometry/tangent_space.h"

#include "glint/geometry/triangle_differentials.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/math/frame.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

/// The angle at corner `a` of triangle (a, b, c); 0 for a degenerate corner.
float corner_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = b - a, e2 = c - a;
    const float l1 = length(e1), l2 = length(e2);
    if (!(l1 > 0.0f) || !(l2 > 0.0f)) return 0.0f;
    return std::acos(std::clamp(dot(e1, e2) / (l1 * l2), -1.0f, 1.0f));
}

}  // namespace

std::vector<Tangent> compute_tangents(const MeshData& data) {
    const std::size_t n = data.positions.size();
    if (data.normals.size() != n || data.uvs.size() != n) return {};
    std::vector<Vec3> along_u(n), up_in_image(n);
    for (std::size_t t = 0; t + 2 < data.indices.size(); t += 3) {
        const uint32_t i[3] = {data.indices[t], data.indices[t + 1], data.indices[t + 2]};
        const Vec3 p[3] = {data.positions[i[0]], data.positions[i[1]], data.positions[i[2]]};
        const TriangleDerivatives d =
            triangle_derivatives(p[0], p[1], p[2], data.uvs[i[0]], data.uvs[i[1]], data.uvs[i[2]]);
        const Vec3 u = unit_or_zero(d.dpdu), up = unit_or_zero(-d.dpdv);
        for (int k = 0; k < 3; ++k) {
            const float angle = corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            along_u[i[k]] += u * angle;
            up_in_image[i[k]] += up * angle;
        }
    }
    std::vector<Tangent> tangents(n);
    for (std::size_t v = 0; v < n; ++v) {
        const Vec3& normal = data.normals[v];
        Vec3 t = unit_or_zero(along_u[v] - normal * dot(normal, along_u[v]));
        if (length(t) == 0.0f) {
            Vec3 b;
            orthonormal_basis(length(normal) > 0.0f ? normal : Vec3(0, 0, 1), t, b);
        }
        tangents[v] = {t, dot(cross(normal, t), up_in_image[v]) < 0.0f ? -1.0f : 1.0f};
    }
    return tangents;
}

}  // namespace glint
