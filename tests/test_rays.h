#pragma once
// Rays the acceleration-structure tests trace.

#include "glint/geometry/triangle_mesh.h"
#include "glint/math/bounds3.h"
#include "glint/math/ray.h"

#include <random>
#include <vector>

namespace glint_test {

/// A direction uniform on the unit sphere: a normalized vector of three Gaussians, which is
/// isotropic (Muller 1959).
inline glint::Vec3 random_unit_vector(std::mt19937& rng) {
    std::normal_distribution<float> normal(0.0f, 1.0f);
    return normalize(glint::Vec3(normal(rng), normal(rng), normal(rng)));
}

/// Rays from a sphere around `box` towards random points in it, a third of them with a
/// finite tmax.
inline std::vector<glint::Ray> random_rays(const glint::Bounds3& box, int count, uint32_t seed) {
    using glint::Vec3;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    const float radius = length(box.diagonal());
    std::vector<glint::Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3 target = box.lo + box.diagonal() * Vec3(uniform(rng), uniform(rng), uniform(rng));
        const Vec3 origin = box.center() + normalize(Vec3(normal(rng), normal(rng), normal(rng))) * radius;
        const Vec3 dir = normalize(target - origin);
        const float tmax = i % 3 == 0 ? radius * (0.5f + uniform(rng)) : glint::kInfinity;
        rays.emplace_back(origin, dir, 0.0f, tmax);
    }
    return rays;
}

/// Points a watertight test must not let a ray slip through: the mesh's vertices and, on
/// every edge, its midpoint and the points a quarter and a third of the way along.
inline std::vector<glint::Vec3> vertices_and_edge_points(const glint::MeshData& m) {
    std::vector<glint::Vec3> points(m.positions.begin(), m.positions.end());
    for (size_t t = 0; t < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const glint::Vec3& a = m.positions[m.indices[t + k]];
            const glint::Vec3& b = m.positions[m.indices[t + (k + 1) % 3]];
            for (float s : {0.5f, 0.25f, 1.0f / 3.0f}) points.push_back(a + (b - a) * s);
        }
    return points;
}

}  // namespace glint_test
