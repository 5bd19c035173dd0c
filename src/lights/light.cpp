#include "glint/lights/light.h"

#include "glint/math/constants.h"
#include "glint/scene_format/param_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

/// Physical irradiance at distance d from a π-scaled intensity.
Color fall_off(const Color& intensity, float distance, Falloff falloff) {
    const Color e = falloff == Falloff::InverseSquare ? intensity / (distance * distance) : intensity;
    return e * kPi;
}

constexpr std::array<std::string_view, 2> kFalloffs{"none", "inverse_square"};

Falloff falloff_from_params(const ParamTable& t) {
    return t.choice("falloff", kFalloffs, "none") == "inverse_square" ? Falloff::InverseSquare : Falloff::None;
}

Vec3 direction_from_params(const ParamTable& t) {
    const Vec3 direction = t.require_vec3("direction");
    if (!(length(direction) > 0.0f)) t.fail("direction", "a non-zero direction");
    return direction;
}

/// A half-angle in degrees from 0 to `max`.
float degrees_from_params(const ParamTable& t, std::string_view key, float fallback, float max) {
    const float a = t.number(key, fallback);
    if (a < 0.0f || a > max) t.fail(key, fmt::format("an angle from 0 to {} degrees", max));
    return a;
}

LightSample delta_sample(const Vec3& direction, float distance, const Color& irradiance) {
    LightSample s;
    s.direction = direction;
    s.distance = distance;
    s.radiance = irradiance;
    s.pdf = 1.0f;
    s.is_delta = true;
    return s;
}

}  // namespace

LightSample PointLight::sample(const Vec3& point, Vec2) const {
    const Vec3 to_light = position_ - point;
    const float d = length(to_light);
    LightSample s = delta_sample(to_light / d, d, fall_off(intensity_, d, falloff_));
    s.point = position_;
    return s;
}

DirectionalLight::DirectionalLight(const Vec3& direction, const Color& irradiance)
    : direction_(normalize(direction)), irradiance_(irradiance) {
    if (!is_finite(direction_)) throw std::invalid_argument("directional light needs a non-zero direction");
}

LightSample DirectionalLight::sample(const Vec3&, Vec2) const {
    return delta_sample(-direction_, kInfinity, irradiance_ * kPi);
}

SpotLight::SpotLight(const Vec3& position, const Vec3& direction, const Color& intensity, float inner_angle,
                     float outer_angle, Falloff falloff)
    : position_(position),
      direction_(normalize(direction)),
      intensity_(intensity),
      cos_inner_(std::cos(inner_angle)),
      cos_outer_(std::cos(outer_angle)),
      falloff_(falloff) {
    if (!is_finite(direction_)) throw std::invalid_argument("spot light needs a non-zero direction");
    if (!(inner_angle >= 0.0f && inner_angle <= outer_angle && outer_angle <= kPi / 2))
        throw std::invalid_argument("spot light needs 0 <= inner angle <= outer angle <= 90 degrees");
}

LightSample SpotLight::sample(const Vec3& point, Vec2) const {
    const Vec3 to_light = position_ - point;
    const float d = length(to_light);
    const Vec3 dir = to_light / d;
    const float cos_angle = dot(-dir, direction_);
    float cone = 1.0f;
    if (cos_angle <= cos_outer_) {
        cone = 0.0f;
    } else if (cos_angle < cos_inner_) {
        const float x = (cos_angle - cos_outer_) / (cos_inner_ - cos_outer_);
        cone = x * x * (3.0f - 2.0f * x);
    }
    LightSample s = delta_sample(dir, d, fall_off(intensity_, d, falloff_) * cone);
    s.point = position_;
    return s;
}

Color emitted_color(const ParamTable& t, std::string_view key) {
    const Color c = t.color(key, Color(1.0f));
    if (c.is_black()) t.fail(key, "a colour with some positive component: a light that emits nothing lights nothing");
    return c;
}

std::unique_ptr<Light> PointLight::from_params(const ParamTable& t) {
    const Color intensity = emitted_color(t, "intensity");
    const Vec3 position = t.require_vec3("position");
    return std::make_unique<PointLight>(position, intensity, falloff_from_params(t));
}

std::unique_ptr<Light> DirectionalLight::from_params(const ParamTable& t) {
    const Color irradiance = emitted_color(t, "intensity");
    return std::make_unique<DirectionalLight>(direction_from_params(t), irradiance);
}

std::unique_ptr<Light> SpotLight::from_params(const ParamTable& t) {
    const Color intensity = emitted_color(t, "intensity");
    const Vec3 position = t.require_vec3("position");
    const Falloff falloff = falloff_from_params(t);
    const Vec3 direction = direction_from_params(t);
    const float outer = degrees_from_params(t, "outer_angle", 30.0f, 90.0f);
    const float inner = degrees_from_params(t, "inner_angle", outer, outer);
    return std::make_unique<SpotLight>(position, direction, intensity, radians(inner), radians(outer), falloff);
}

}  // namespace glint
