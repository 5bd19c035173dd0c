#pragma once
/// \file Hit records: a cheap one for traversal, a full one for shading.
///
/// Traversal only keeps t, which primitive, and two parameters (barycentrics for
/// triangles). The full `SurfaceInteraction` is computed once, for the closest hit
/// (the pbrt-v4 / Mitsuba 3 two-phase split).

#include "glint/math/color.h"
#include "glint/math/constants.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <array>
#include <cstdint>

namespace glint {

inline constexpr uint32_t kNoHit = 0xffffffffu;

struct Hit {
    float t = kInfinity;
    /// Index of the scene object that was hit (kNoHit if none).
    uint32_t object = kNoHit;
    /// Primitive inside the object: triangle index, heightfield cell, box face...
    uint32_t primitive = 0;
    /// Shape-specific parameters; for triangles the barycentric weights of v1 and v2.
    float u = 0.0f, v = 0.0f;

    [[nodiscard]] bool found() const { return object != kNoHit; }
};

struct SurfaceInteraction {
    Vec3 p;
    /// Unit normal of the true surface, on the side the shape calls outside
    /// (for triangles: the side from which the vertices appear counter-clockwise).
    Vec3 geometric_normal;
    /// Unit interpolated normal, flipped if needed to lie on geometric_normal's side.
    Vec3 shading_normal;
    Vec2 uv;
    /// ∂p/∂u and ∂p/∂v: how the point moves with the texture coordinates (pbrt-v4's
    /// SurfaceInteraction), zero where the shape has no such map. Their cross product's length
    /// is the surface area one unit of uv covers, which sets a texture lookup's footprint.
    Vec3 dpdu, dpdv;
    /// The tangent a normal map's +x (red) follows, interpolated from a mesh's vertex
    /// tangents (geometry/tangent_space.h), and the sign that makes sign·(n × tangent) its +y;
    /// zero where the shape has none (a normal map then takes ∂p/∂u and −∂p/∂v).
    Vec3 tangent;
    float tangent_sign = 1.0f;
    /// How fast the normal turns along the surface (1/radius: 1/r on a sphere, 0 on a plane),
    /// an isotropic estimate; it widens a ray cone reflected or refracted here.
    float curvature = 0.0f;
    /// The width, in units of uv, of the surface region the ray's cone covers here
    /// (integrators/ray_cone.h): set by the integrator, 0 for a point lookup.
    float uv_footprint = 0.0f;
    /// The mesh's interpolated vertex colour (linear), white where it has none.
    Color vertex_color{1.0f};
    /// True if the ray arrived from the side geometric_normal points to.
    bool front_face = true;
    /// Scene material index; with per-vertex materials, the three corners' materials
    /// and their barycentric weights (handout §6.1.1).
    std::array<uint32_t, 3> materials{0, 0, 0};
    std::array<float, 3> material_weights{1.0f, 0.0f, 0.0f};
    bool blends_materials = false;
    /// The time of the ray that hit (motion blur): rays spawned here travel at it.
    float time = 0.0f;
};

}  // namespace glint
