#pragma once
/// \file Warps from the unit square to the domains a path tracer samples: disk, hemisphere,
/// sphere, cone, triangle, regular polygon and a cosine-power lobe, each with its density.
///
/// Every direction is in a local frame whose +z is the normal or axis (turn it into world
/// space with `orthonormal_basis`, math/frame.h). The `u` components are in [0, 1). Solid-angle
/// densities are per steradian, the disk's per unit area. Each warp inverts the CDF of its
/// density (pbrt-v4, "Sampling Algorithms", chapter A.5); tests/sampling_test.cpp checks every
/// pair with a chi-square test.

#include "glint/math/constants.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace glint {

/// The unit direction with polar angle θ (given as sin θ and cos θ) and azimuth φ about +z.
[[nodiscard]] inline Vec3 spherical_direction(float sin_theta, float cos_theta, float phi) {
    // Clamped because callers' sin and cos may stray past ±1 by a rounding step.
    const float s = std::clamp(sin_theta, -1.0f, 1.0f);
    return {s * std::cos(phi), s * std::sin(phi), std::clamp(cos_theta, -1.0f, 1.0f)};
}

/// sin θ from cos θ. Written as √((1 − cos θ)(1 + cos θ)) rather than √(1 − cos²θ): near
/// cos θ = ±1 the product keeps the digits that 1 − cos²θ cancels away.
[[nodiscard]] inline float sin_from_cos(float cos_theta) {
    return std::sqrt(std::max(0.0f, (1.0f - cos_theta) * (1.0f + cos_theta)));
}

/// Shirley & Chiu, "A Low Distortion Map Between Disk and Square", JGT 2(3), 1997: the
/// concentric map. Square [-1,1]² rings go to disk rings, so strata stay compact and
/// area-proportional (density 1/π, `uniform_disk_pdf`), unlike the polar map r = √u0.
[[nodiscard]] inline Vec2 sample_uniform_disk_concentric(Vec2 u) {
    const float ox = 2.0f * u.x - 1.0f;
    const float oy = 2.0f * u.y - 1.0f;
    if (ox == 0.0f && oy == 0.0f) return {0.0f, 0.0f};
    // The wedge |x| > |y| maps to the sector |φ| < π/4 (and its mirror); the other wedge to
    // the sectors around ±π/2. r is the larger coordinate, φ is linear in the smaller one.
    float r, phi;
    if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        phi = (kPi / 4.0f) * (oy / ox);
    } else {
        r = oy;
        phi = kPi / 2.0f - (kPi / 4.0f) * (ox / oy);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

/// Density of `sample_uniform_disk_concentric` per unit area of the unit disk: 1/π.
[[nodiscard]] constexpr float uniform_disk_pdf() { return kInvPi; }

/// Malley's method: lift a uniform disk point onto the hemisphere, z = √(1 − x² − y²). The
/// projection of cos θ dω onto the disk is area, so the result has density cos θ / π
/// (Pharr, Jakob & Humphreys, pbrt-v4, section A.5.3).
[[nodiscard]] inline Vec3 sample_cosine_hemisphere(Vec2 u) {
    const Vec2 d = sample_uniform_disk_concentric(u);
    return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

/// Density of `sample_cosine_hemisphere` per steradian: max(cos θ, 0)/π.
[[nodiscard]] inline float cosine_hemisphere_pdf(float cos_theta) { return std::max(cos_theta, 0.0f) * kInvPi; }

/// Uniform over the hemisphere z ≥ 0. Archimedes: the area of a sphere zone is proportional to
/// its height, so cos θ = u0 is uniform in solid angle; φ = 2π u1.
[[nodiscard]] inline Vec3 sample_uniform_hemisphere(Vec2 u) {
    const float cos_theta = u.x;
    return spherical_direction(sin_from_cos(cos_theta), cos_theta, 2.0f * kPi * u.y);
}

/// Density of `sample_uniform_hemisphere` per steradian: 1/(2π).
[[nodiscard]] constexpr float uniform_hemisphere_pdf() { return 0.5f * kInvPi; }

/// Uniform over the unit sphere: cos θ = 1 − 2 u0 (Archimedes again), φ = 2π u1.
[[nodiscard]] inline Vec3 sample_uniform_sphere(Vec2 u) {
    const float cos_theta = 1.0f - 2.0f * u.x;
    // sin²θ = (1 − cos θ)(1 + cos θ) = 4 u0 (1 − u0), exact in u0 near both poles.
    const float sin_theta = 2.0f * std::sqrt(std::max(0.0f, u.x * (1.0f - u.x)));
    return spherical_direction(sin_theta, cos_theta, 2.0f * kPi * u.y);
}

/// Density of `sample_uniform_sphere` per steradian: 1/(4π).
[[nodiscard]] constexpr float uniform_sphere_pdf() { return 0.25f * kInvPi; }

/// Uniform over the cap of directions within θmax of +z: cos θ uniform in [cos θmax, 1]
/// (pbrt-v4's `SampleUniformCone`). For small cones, where lights subtend a few pixels, the
/// sample is built from 1 − cos θ = u0 (1 − cos θmax) instead of cos θ: the
/// difference 1 − cos θmax is exact in float for cos θmax ≥ 1/2 (Sterbenz), and
/// sin²θ = (1 − cos θ)(1 + cos θ) then keeps full relative precision, where 1 − cos²θ would
/// round a 0.01° cone to a handful of float steps.
[[nodiscard]] inline Vec3 sample_uniform_cone(Vec2 u, float cos_theta_max) {
    const float one_minus_cos = u.x * (1.0f - cos_theta_max);
    const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
    return spherical_direction(sin_theta, 1.0f - one_minus_cos, 2.0f * kPi * u.y);
}

/// Density of `sample_uniform_cone` per steradian: 1/(2π(1 − cos θmax)), the inverse of the
/// cap's solid angle. Infinite for cos θmax = 1 (a degenerate cone is a delta direction).
[[nodiscard]] inline float uniform_cone_pdf(float cos_theta_max) {
    return 1.0f / (2.0f * kPi * (1.0f - cos_theta_max));
}

/// Barycentrics (b0, b1, b2) uniform over a triangle's area: Heitz, "A Low-Distortion Map
/// Between Triangle and Square", 2019 (as in pbrt-v4's `SampleUniformTriangle`). It shifts
/// the smaller coordinate by half of it instead of folding or taking a square root, so nearby
/// u stay nearby and stratification survives. Any triangle is an affine image of the unit one
/// and affine maps scale area uniformly: the density is 1/area of the mapped triangle.
[[nodiscard]] inline std::array<float, 3> sample_uniform_triangle(Vec2 u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = 0.5f * u.x;
        b1 = u.y - b0;
    } else {
        b1 = 0.5f * u.y;
        b0 = u.x - b1;
    }
    return {b0, b1, 1.0f - b0 - b1};
}

/// Points uniform over the regular polygon with `sides` (≥ 3) corners on the unit circle,
/// the first at angle `rotation` (radians): u.x picks one of the equal wedges (centre, corner
/// k, corner k+1) and is rescaled, so strata in u.x stay strata; the wedge is then sampled by
/// `sample_uniform_triangle`. Density 1/`regular_polygon_area(sides)`. A camera's aperture
/// with blades (bokeh shaped like the diaphragm). The corners' cosines and sines are computed
/// when the polygon is made: per sample they were two sincos, 4 % of a render with depth of
/// field (docs/performance.md, "Sampler draws without divisions").
class UniformRegularPolygon {
public:
    UniformRegularPolygon(uint32_t sides, float rotation) {
        const float step = 2.0f * kPi / float(sides);
        wedges_.reserve(sides);
        for (uint32_t k = 0; k < sides; ++k) {
            // Each wedge its own two corners: a0 + step may round apart from the next
            // wedge's a0 by an ulp, far below any visible seam.
            const float a0 = rotation + step * float(k), a1 = a0 + step;
            wedges_.push_back({std::cos(a0), std::sin(a0), std::cos(a1), std::sin(a1)});
        }
    }

    [[nodiscard]] Vec2 sample(Vec2 u) const {
        const auto sides = uint32_t(wedges_.size());
        const float scaled = u.x * float(sides);
        const uint32_t k = std::min(uint32_t(scaled), sides - 1);
        const Wedge& w = wedges_[k];
        // Barycentrics of (centre, corner k, corner k+1); the centre is the origin.
        const std::array<float, 3> b = sample_uniform_triangle({scaled - float(k), u.y});
        return {b[1] * w.cos0 + b[2] * w.cos1, b[1] * w.sin0 + b[2] * w.sin1};
    }

private:
    struct Wedge {
        float cos0, sin0, cos1, sin1;
    };
    std::vector<Wedge> wedges_;
};

/// Area of the regular polygon with `sides` corners on the unit circle: (n/2)·sin(2π/n).
[[nodiscard]] inline float regular_polygon_area(uint32_t sides) {
    return 0.5f * float(sides) * std::sin(2.0f * kPi / float(sides));
}

/// Directions about +z with density (n+1)/(2π) cos^n θ on the upper hemisphere (Phong's lobe;
/// with the half-vector, Blinn-Phong's). Its CDF in cos θ is cos^(n+1) θ, so
/// cos θ = (1 − u0)^(1/(n+1)); 1 − u0 is in (0, 1], which keeps samples off the horizon,
/// where the density is zero. `exponent` must be > −1.
[[nodiscard]] inline Vec3 sample_phong_lobe(Vec2 u, float exponent) {
    const float cos_theta = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));
    return spherical_direction(sin_from_cos(cos_theta), cos_theta, 2.0f * kPi * u.y);
}

/// Density of `sample_phong_lobe` per steradian: (n+1)/(2π) cos^n θ for cos θ > 0, else 0.
[[nodiscard]] inline float phong_lobe_pdf(float cos_theta, float exponent) {
    if (cos_theta <= 0.0f) return 0.0f;
    return (exponent + 1.0f) * (0.5f * kInvPi) * std::pow(cos_theta, exponent);
}

}  // namespace glint
