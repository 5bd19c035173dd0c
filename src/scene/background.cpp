#include "glint/scene/background.h"

#include "glint/image/image_sampling.h"
#include "glint/math/constants.h"

#include <algorithm>
#include <cmath>

namespace glint {

Vec2 equirectangular_uv(const Vec3& d) {
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
    return {u, v};
}

Vec2 sphere_map_uv(const Vec3& d) {
    // Ball normal n = normalize(d + (0,0,1)); the image shows (n.x, n.y) in [-1, 1]².
    const float denom = std::sqrt(std::max(2.0f * (1.0f + d.z), 0.0f));
    float nx = 0.0f, ny = 0.0f;
    if (denom > 1e-7f) {
        nx = d.x / denom;
        ny = d.y / denom;
    } else {
        nx = 1.0f;  // d = -z maps to the whole rim; pick its right-hand point
    }
    return {0.5f * (nx + 1.0f), 0.5f * (1.0f - ny)};
}

Vec2 angular_map_uv(const Vec3& d) {
    const float rho = std::acos(std::clamp(-d.z, -1.0f, 1.0f)) / kPi;
    const float across = std::sqrt(d.x * d.x + d.y * d.y);
    // On the axis the azimuth is undefined: -z is the centre, +z the whole rim (pick its right-hand point).
    const float s = across > 1e-7f ? rho * d.x / across : rho;
    const float t = across > 1e-7f ? rho * d.y / across : 0.0f;
    return {0.5f * (s + 1.0f), 0.5f * (1.0f - t)};
}

Vec3 equirectangular_direction(Vec2 uv) {
    const float phi = 2.0f * kPi * (uv.x - 0.5f), theta = kPi * uv.y;
    const float sin_theta = std::sin(theta);
    return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

std::optional<Vec3> sphere_map_direction(Vec2 uv) {
    // The ball's normal n = (s, t, √(1 − s² − t²)) reflects the view -z into d = 2 n_z n − z.
    const float s = 2.0f * uv.x - 1.0f, t = 1.0f - 2.0f * uv.y;
    const float r2 = s * s + t * t;
    if (r2 > 1.0f) return std::nullopt;
    const float nz = std::sqrt(1.0f - r2);
    return Vec3(2.0f * nz * s, 2.0f * nz * t, 2.0f * nz * nz - 1.0f);
}

std::optional<Vec3> angular_map_direction(Vec2 uv) {
    const float s = 2.0f * uv.x - 1.0f, t = 1.0f - 2.0f * uv.y;
    const float rho = std::sqrt(s * s + t * t);
    if (rho > 1.0f) return std::nullopt;
    if (rho == 0.0f) return Vec3(0.0f, 0.0f, -1.0f);
    const float angle = kPi * rho;  // from -z
    const float across = std::sin(angle) / rho;
    return Vec3(across * s, across * t, -std::cos(angle));
}

Background Background::constant(const Color& color) {
    Background b;
    b.color_ = color;
    return b;
}

Background Background::environment(BackgroundKind kind, std::shared_ptr<const Image> image, float rotation_degrees,
                                   float scale) {
    Background b;
    b.kind_ = kind;
    b.image_ = std::move(image);
    b.cos_rotation_ = std::cos(radians(rotation_degrees));
    b.sin_rotation_ = std::sin(radians(rotation_degrees));
    b.scale_ = scale;
    return b;
}

Vec2 Background::uv_of(const Vec3& direction) const {
    // Rotating the map by +θ about y equals looking it up with the direction rotated by -θ.
    const Vec3 d = normalize(direction);
    const Vec3 r(cos_rotation_ * d.x - sin_rotation_ * d.z, d.y, sin_rotation_ * d.x + cos_rotation_ * d.z);
    switch (kind_) {
    case BackgroundKind::SphereMap: return sphere_map_uv(r);
    case BackgroundKind::AngularMap: return angular_map_uv(r);
    default: return equirectangular_uv(r);
    }
}

std::optional<Vec3> Background::direction_of(Vec2 uv) const {
    std::optional<Vec3> r;
    switch (kind_) {
    case BackgroundKind::SphereMap: r = sphere_map_direction(uv); break;
    case BackgroundKind::AngularMap: r = angular_map_direction(uv); break;
    default: r = equirectangular_direction(uv); break;
    }
    if (!r) return std::nullopt;
    // The map's direction turned by +θ about y (uv_of's rotation undone).
    return Vec3(cos_rotation_ * r->x + sin_rotation_ * r->z, r->y, -sin_rotation_ * r->x + cos_rotation_ * r->z);
}

Color Background::evaluate(const Vec3& direction) const {
    if (kind_ == BackgroundKind::Constant || !image_) return color_;
    const Vec2 uv = uv_of(direction);
    // Bilinear: an environment seen directly fills many pixels per texel. Longitude wraps
    // around in a latitude-longitude map; everything else clamps at the border.
    const WrapMode wrap_u = kind_ == BackgroundKind::Equirectangular ? WrapMode::Repeat : WrapMode::Clamp;
    return sample_bilinear_color(*image_, uv, wrap_u, WrapMode::Clamp) * scale_;
}

}  // namespace glint
