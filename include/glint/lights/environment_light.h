#pragma once
/// \file The background as a light at infinity, importance-sampled (pbrt-v4's
/// ImageInfiniteLight and UniformInfiniteLight). Units: the map's radiance (docs/units.md).

#include "glint/lights/light.h"
#include "glint/sampling/piecewise_constant_2d.h"
#include "glint/scene/background.h"

#include <memory>
#include <optional>

namespace glint {

/// Radiance arriving from every direction as the Background says, rotation and intensity
/// included. A map is sampled in proportion to what it sends: a PiecewiseConstant2D over its
/// pixels, each weighted by its luminance (the average of the bilinear lookup over the
/// pixel, so that every direction with radiance has density) times the solid angle its
/// pixel covers, dω/(du dv) at its centre:
/// - equirect (θ = πv, φ = 2πu): 2π² sin θ;
/// - sphere map (mirror ball, direction at twice the ball normal's angle): dω = 4 dA on the
///   unit disk, 16 du dv, the same everywhere; pixels whose centre is off the disk weigh 0;
/// - angular map (angle πρ at radius ρ): dω = π sin(πρ)/ρ dA, 4π sin(πρ)/ρ du dv.
/// The solid-angle density is then p(u, v) / (dω/(du dv)) at the sampled point (pbrt-v4,
/// section 12.5.2). A constant colour is sampled cosine-weighted about the receiver's
/// normal, cos θ/π (uniformly over the sphere, 1/(4π), where there is no receiver): a
/// diffuse surface's own density, so that a white diffuse object under a white sky is
/// noiseless (both MIS strategies give exactly half).
class EnvironmentLight final : public Light {
public:
    /// The light of `background`, or null when it sends nothing (black, or an all-black map).
    [[nodiscard]] static std::unique_ptr<EnvironmentLight> of(const Background& background);

    [[nodiscard]] LightSample sample(const Vec3& point, Vec2 u) const override;
    [[nodiscard]] LightSample sample_at_surface(const Vec3& point, const Vec3& normal, Vec2 u) const override;
    /// A zero `normal` stands for no receiver (sample()'s density).
    [[nodiscard]] float pdf_direction(const Vec3& direction, const Vec3& normal) const override;
    [[nodiscard]] std::string_view type_name() const override { return "environment"; }

private:
    EnvironmentLight(const Background& background, std::optional<PiecewiseConstant2D> distribution);

    /// dω/(du dv) of the map at image coordinates uv (0 off a disk-shaped map's disk).
    [[nodiscard]] float solid_angle_per_uv(Vec2 uv) const;

    Background background_;
    /// Over the map's pixels; none for a constant colour.
    std::optional<PiecewiseConstant2D> distribution_;
};

}  // namespace glint
