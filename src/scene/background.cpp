#include "glint/scene/background.h"

#include "glint/image/image_sampling.h"
#include "glint/math/constants.h"

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

Color Background::evaluate(const Vec3& direction) const {
    if (kind_ == BackgroundKind::Constant || !image_) return color_;
    // Rotating the map by +θ about y equals looking it up with the direction rotated by -θ.
    const Vec3 d = normalize(direction);
    const Vec3 r(cos_rotation_ * d.x - sin_rotation_ * d.z, d.y, sin_rotation_ * d.x + cos_rotation_ * d.z);
    const Vec2 uv = kind_ == BackgroundKind::Equirectangular ? equirectangular_uv(r) : sphere_map_uv(r);
    // Bilinear: an environment seen directly fills many pixels per texel. Longitude wraps
    // around in a latitude-longitude map; everything else clamps at the border.
    const WrapMode wrap_u = kind_ == BackgroundKind::Equirectangular ? WrapMode::Repeat : WrapMode::Clamp;
    return sample_bilinear_color(*image_, uv, wrap_u, WrapMode::Clamp) * scale_;
}

}  // namespace glint
