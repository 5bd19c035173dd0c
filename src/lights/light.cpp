#include "glint/lights/light.h"

#include "glint/math/constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

/// Physical irradiance at distance d from a π-scaled intensity.
Color fall_off(const Color& intensity, float distance, Falloff falloff) {
    const Color e = falloff == Falloff::InverseSquare ? intensity / (distance * distance) : intensity;
    return e * kPi;
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

}  // namespace glint
