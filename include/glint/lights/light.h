#pragma once
/// \file Light sources. Units and conventions: docs/units.md.
///
/// A light gives, at a receiving point, the direction towards it, its distance, and the
/// irradiance-like quantity E such that a white Lambertian surface facing the light
/// reflects radiance E (Glint folds BRDF 1/π into light units, as the assignments do:
/// L = kd·E·cosθ).

#include "glint/math/color.h"
#include "glint/math/vec3.h"

#include <string_view>

namespace glint {

struct LightSample {
    /// Unit vector from the receiving point towards the light.
    Vec3 direction;
    /// Distance to the light (kInfinity for directional lights): the shadow ray's tmax.
    float distance = 0.0f;
    /// E at normal incidence; zero outside a spot light's cone.
    Color irradiance;
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
    virtual ~Light() = default;
    [[nodiscard]] virtual LightSample sample(const Vec3& point) const = 0;
    [[nodiscard]] virtual std::string_view type_name() const = 0;
};

class PointLight final : public Light {
public:
    PointLight(const Vec3& position, const Color& intensity, Falloff falloff)
        : position_(position), intensity_(intensity), falloff_(falloff) {}
    [[nodiscard]] LightSample sample(const Vec3& point) const override;
    [[nodiscard]] std::string_view type_name() const override { return "point"; }
    [[nodiscard]] const Vec3& position() const { return position_; }
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
    [[nodiscard]] LightSample sample(const Vec3& point) const override;
    [[nodiscard]] std::string_view type_name() const override { return "directional"; }
    [[nodiscard]] const Vec3& direction() const { return direction_; }
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
    [[nodiscard]] LightSample sample(const Vec3& point) const override;
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
