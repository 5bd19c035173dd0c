#pragma once
/// \file What a triangle's texture lookups and ray cones need of it: ∂p/∂u and ∂p/∂v from its
/// corners' positions and texture coordinates (pbrt-v4, Triangle::InteractionFromIntersection),
/// and how fast its vertex normals turn across it.

#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <cmath>

namespace glint {

struct TriangleDerivatives {
    Vec3 dpdu, dpdv;
};

/// Solve [p0 − p2, p1 − p2] = [dpdu, dpdv]·[uv0 − uv2, uv1 − uv2] for the triangle's linear
/// map from uv to the surface. Zero vectors when the texture coordinates are degenerate
/// (a triangle mapped onto a line or a point has no such map).
[[nodiscard]] inline TriangleDerivatives triangle_derivatives(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                                              const Vec2& uv0, const Vec2& uv1, const Vec2& uv2) {
    const Vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    const Vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    const float determinant = duv02.x * duv12.y - duv02.y * duv12.x;
    if (!(std::abs(determinant) > 1e-12f) || !std::isfinite(determinant)) return {};
    const float inv = 1.0f / determinant;
    return {(dp02 * duv12.y - dp12 * duv02.y) * inv, (dp12 * duv02.x - dp02 * duv12.x) * inv};
}

/// The curvature the vertex normals describe: the mean over the three edges of the angle
/// the normal turns per unit length, |n_i − n_j| / |p_i − p_j| (exactly 1/r for a sphere's
/// chords with its true normals). 0 for equal normals: flat facets reflect cones unwidened.
[[nodiscard]] inline float triangle_curvature(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& n0,
                                              const Vec3& n1, const Vec3& n2) {
    auto edge = [](const Vec3& pa, const Vec3& pb, const Vec3& na, const Vec3& nb) {
        const float d = length(pa - pb);
        return d > 0.0f ? length(na - nb) / d : 0.0f;
    };
    const float k = (edge(p0, p1, n0, n1) + edge(p1, p2, n1, n2) + edge(p2, p0, n2, n0)) / 3.0f;
    return std::isfinite(k) ? k : 0.0f;
}

}  // namespace glint
