#pragma once
/// \file Ray cones (Akenine-Möller et al., "Texture Level of Detail Strategies for Real-Time
/// Ray Tracing", Ray Tracing Gems 2019, ch. 20; "Improved Shader and Texture Level of Detail
/// Using Ray Cones", JCGT 2021): each ray carries the cone of directions one pixel sample
/// stands for, as a width at its origin and a spread angle. At a hit the cone's width, over
/// the surface's uv scale and stretched by the obliquity of the hit, is the footprint a
/// texture lookup filters over (materials/texture.h); reflected and refracted rays carry the
/// cone on, widened by the surface's curvature, so that a texture seen in a mirror or through
/// glass is filtered for the distance it is really seen at.

#include "glint/geometry/hit.h"
#include "glint/math/ray.h"
#include "glint/math/vec3.h"

#include <algorithm>
#include <cmath>

namespace glint {

class Camera;

struct RayCone {
    /// Width (world units) at the ray's origin.
    float width = 0.0f;
    /// Spread angle (radians): how fast the width grows per unit of distance.
    float spread = 0.0f;

    /// The cone `distance` along the ray.
    [[nodiscard]] RayCone at(float distance) const { return {width + spread * distance, spread}; }

    /// The cone of a ray leaving a surface hit by this one (already moved there with at()),
    /// by a mirror reflection, refraction or a sampled bounce: the normal turns by about
    /// curvature·width across the footprint, which a reflection doubles (Akenine-Möller et al.
    /// 2019, eq. 20.31, with the surface spread angle from the curvature instead of screen-space
    /// normal differences). Convex and concave surfaces both widen it: blurring a texture a
    /// concave mirror focuses is the safe error, aliasing it the visible one.
    [[nodiscard]] RayCone bounced(float curvature) const { return {width, spread + 2.0f * curvature * width}; }

    /// The width, in units of uv, that this cone (arrived at the hit) covers on the surface
    /// of `si`, hit along `direction`: its width over the length one unit of uv spans there
    /// (the square root of |∂p/∂u × ∂p/∂v|, an isotropic footprint), divided by |cos θ| for the
    /// elongation of an oblique hit (eq. 20.36's log2|n·d| term). 0 when the surface has no
    /// uv map or the cone no width: a point lookup.
    [[nodiscard]] float uv_footprint(const SurfaceInteraction& si, const Vec3& direction) const {
        const float uv_area = length(cross(si.dpdu, si.dpdv));
        if (!(uv_area > 0.0f) || !(width > 0.0f)) return 0.0f;
        const float cos_theta = std::abs(dot(si.geometric_normal, direction)) / length(direction);
        // Grazing hits stretch the footprint without bound; past 1/1000 the coarsest level
        // of any texture is reached anyway.
        return width / (std::max(cos_theta, 1e-3f) * std::sqrt(uv_area));
    }
};

/// The cone of a camera ray of a `height`-pixel image taken with `samples_per_axis`² samples
/// per pixel: a perspective camera's rays spread by the angle one pixel subtends at the
/// image centre, 2·tan(fov/2)/height; an orthographic camera's keep one pixel's width. As
/// pbrt-v4's camera ray differentials, the pixel is divided by the samples per axis (at most
/// 8): supersampling already averages over the pixel, and the texture filter need only cover
/// the share between samples.
[[nodiscard]] RayCone camera_ray_cone(const Camera& camera, uint32_t height, uint32_t samples_per_axis);

}  // namespace glint
