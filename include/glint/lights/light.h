#pragma once
/// \file Light sources. Units and conventions: docs/units.md.
///
/// Every light answers, for a receiving point and a uniform 2-D sample u: a direction
/// towards the light, the distance, the radiance arriving along it, and the solid-angle
/// density of that direction (pbrt-v4's `Light::SampleLi`). Point-like lights are Dirac
/// deltas: one direction, pdf 1, and "radiance" is the irradiance they deliver at normal
/// incidence. All returned quantities are physical; the scene-file parameters of point,
/// spot and directional lights are π-scaled (a white Lambertian surface facing a light of
/// intensity 1 with no falloff shows radiance 1), so these lights return π × parameter.

#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <memory>
#include <string_view>

namespace glint {

class BuildContext;
class ParamTable;

struct LightSample {
    /// Unit vector from the receiving point towards the light.
    Vec3 direction;
    /// Distance to the sampled point (kInfinity for directional lights and the environment).
    float distance = 0.0f;
    /// Radiance arriving along `direction` (delta lights: the irradiance at normal incidence,
    /// zero outside a spot light's cone).
    Color radiance;
    /// Density of `direction` per unit solid angle; 1 for delta lights. 0 = no sample.
    float pdf = 0.0f;
    bool is_delta = true;
    /// The sampled point and its unit normal facing the receiver (area lights): the shadow
    /// ray ends just off this surface so that the light's own geometry does not block it.
    Vec3 point;
    Vec3 normal;
};

/// How a point or spot light's intensity decays with distance d.
enum class Falloff {
    /// E = I: the assignments' lights, whose strength does not depend on distance.
    None,
    /// E = I / d²: physical point lights.
    InverseSquare,
};

class Light {
public:
    /// `delta`: a point-like light (see is_delta).
    explicit Light(bool delta = true) : delta_(delta) {}
    virtual ~Light() = default;
    /// Sample the light from `point` with u in [0,1)² (ignored by delta lights).
    [[nodiscard]] virtual LightSample sample(const Vec3& point, Vec2 u) const = 0;
    /// Solid-angle density with which sample(ref, ·) returns the light point p (unit normal
    /// n); 0 for delta lights, which no ray can hit.
    [[nodiscard]] virtual float pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const {
        (void)ref, (void)p, (void)n;
        return 0.0f;
    }
    /// sample() for a receiving surface point whose shading normal is `normal`: a light whose
    /// density can follow the receiver's cosine (a uniform sky) does; others ignore it.
    [[nodiscard]] virtual LightSample sample_at_surface(const Vec3& point, const Vec3& normal, Vec2 u) const {
        (void)normal;
        return sample(point, u);
    }
    /// Solid-angle density with which sample_at_surface(·, normal, ·) returns `direction`
    /// (unit or not), for lights at infinity that a ray leaving the scene reaches (the
    /// environment): MIS weighs such a ray against light sampling with it. 0 for the others,
    /// which a ray finds at a point (pdf above) or never.
    [[nodiscard]] virtual float pdf_direction(const Vec3& direction, const Vec3& normal) const {
        (void)direction, (void)normal;
        return 0.0f;
    }
    /// True for point-like lights, which one sample covers. A flag, not a virtual call: the
    /// Whitted integrator asks for every light at every hit.
    [[nodiscard]] bool is_delta() const { return delta_; }
    [[nodiscard]] virtual std::string_view type_name() const = 0;

private:
    bool delta_;
};

/// The colour of `key` (white when absent) for a light's intensity or radiance; throws
/// SceneError if it is black (a light that emits nothing is a mistake).
[[nodiscard]] Color emitted_color(const ParamTable& params, std::string_view key);

class PointLight final : public Light {
public:
    PointLight(const Vec3& position, const Color& intensity, Falloff falloff)
        : position_(position), intensity_(intensity), falloff_(falloff) {}
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Light> from_params(const ParamTable& params);
    [[nodiscard]] LightSample sample(const Vec3& point, Vec2 u) const override;
    [[nodiscard]] std::string_view type_name() const override { return "point"; }
    [[nodiscard]] const Vec3& position() const { return position_; }
    /// π-scaled intensity, as written in the scene.
    [[nodiscard]] const Color& intensity() const { return intensity_; }
    [[nodiscard]] Falloff falloff() const { return falloff_; }

private:
    Vec3 position_;
    Color intensity_;
    Falloff falloff_;
};

/// Light from infinitely far away, travelling along `direction`.
class DirectionalLight final : public Light {
public:
    DirectionalLight(const Vec3& direction, const Color& irradiance);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Light> from_params(const ParamTable& params);
    [[nodiscard]] LightSample sample(const Vec3& point, Vec2 u) const override;
    [[nodiscard]] std::string_view type_name() const override { return "directional"; }
    [[nodiscard]] const Vec3& direction() const { return direction_; }
    /// π-scaled irradiance, as written in the scene.
    [[nodiscard]] const Color& irradiance() const { return irradiance_; }

private:
    Vec3 direction_;
    Color irradiance_;
};

/// A point light restricted to a cone around `direction`: full intensity inside
/// `inner_angle`, smoothly (smoothstep in cos θ, as glTF's KHR_lights_punctual) to zero at
/// `outer_angle`. Angles are half-angles in radians.
class SpotLight final : public Light {
public:
    SpotLight(const Vec3& position, const Vec3& direction, const Color& intensity, float inner_angle,
              float outer_angle, Falloff falloff);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Light> from_params(const ParamTable& params);
    [[nodiscard]] LightSample sample(const Vec3& point, Vec2 u) const override;
    [[nodiscard]] std::string_view type_name() const override { return "spot"; }
    [[nodiscard]] const Vec3& position() const { return position_; }

private:
    Vec3 position_;
    Vec3 direction_;
    Color intensity_;
    float cos_inner_, cos_outer_;
    Falloff falloff_;
};

}  // namespace glint
