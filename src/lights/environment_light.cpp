#include "glint/lights/environment_light.h"

#include "glint/math/constants.h"
#include "glint/math/frame.h"
#include "glint/sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace glint {

namespace {

/// dω/(du dv) of each layout (environment_light.h has the derivations).
float layout_solid_angle_per_uv(BackgroundKind kind, Vec2 uv) {
    if (kind == BackgroundKind::Equirectangular) return 2.0f * kPi * kPi * std::sin(kPi * uv.y);
    const float s = 2.0f * uv.x - 1.0f, t = 1.0f - 2.0f * uv.y;
    const float rho = std::sqrt(s * s + t * t);
    if (rho > 1.0f) return 0.0f;
    if (kind == BackgroundKind::SphereMap) return 16.0f;
    // Angular map: sin(πρ)/ρ → π at the centre.
    return 4.0f * kPi * (rho > 1e-6f ? std::sin(kPi * rho) / rho : kPi);
}

/// Luminance of pixel (x, y), ≥ 0 (NaN and negative values of a broken map count as 0).
float pixel_luminance(const Image& image, int x, int y) {
    const float l = image.rgb(x, y).luminance();
    return l > 0.0f && std::isfinite(l) ? l : 0.0f;
}

/// The mean of the bilinear lookup over each pixel: the tent filter integrated over a
/// pixel weighs its own texel 3/4 and each neighbour 1/8 per axis. Where the lookup
/// wraps (an equirect map's longitude), so does this; elsewhere it clamps.
std::vector<float> pixel_means(const Image& image, bool wrap_x) {
    const int w = image.width, h = image.height;
    auto column = [&](int x) { return wrap_x ? (x + w) % w : std::clamp(x, 0, w - 1); };
    std::vector<float> across(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            across[std::size_t(y) * w + x] =
                0.75f * pixel_luminance(image, x, y) +
                0.125f * (pixel_luminance(image, column(x - 1), y) + pixel_luminance(image, column(x + 1), y));
    std::vector<float> mean(across.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t above = std::size_t(std::max(y - 1, 0)) * w + x;
            const std::size_t below = std::size_t(std::min(y + 1, h - 1)) * w + x;
            mean[std::size_t(y) * w + x] =
                0.75f * across[std::size_t(y) * w + x] + 0.125f * (across[above] + across[below]);
        }
    return mean;
}

}  // namespace

std::unique_ptr<EnvironmentLight> EnvironmentLight::of(const Background& background) {
    const Image* image = background.image();
    if (background.kind() == BackgroundKind::Constant || !image) {
        if (background.color().is_black()) return nullptr;
        return std::unique_ptr<EnvironmentLight>(new EnvironmentLight(background, std::nullopt));
    }
    if (!(background.scale() > 0.0f)) return nullptr;
    std::vector<float> weights = pixel_means(*image, background.kind() == BackgroundKind::Equirectangular);
    bool any = false;
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) {
            const Vec2 centre((float(x) + 0.5f) / float(image->width), (float(y) + 0.5f) / float(image->height));
            float& w = weights[std::size_t(y) * image->width + x];
            w *= layout_solid_angle_per_uv(background.kind(), centre);
            any = any || w > 0.0f;
        }
    if (!any) return nullptr;
    return std::unique_ptr<EnvironmentLight>(
        new EnvironmentLight(background, PiecewiseConstant2D(weights, image->width, image->height)));
}

EnvironmentLight::EnvironmentLight(const Background& background, std::optional<PiecewiseConstant2D> distribution)
    : Light(false), background_(background), distribution_(std::move(distribution)) {}

float EnvironmentLight::solid_angle_per_uv(Vec2 uv) const { return layout_solid_angle_per_uv(background_.kind(), uv); }

LightSample EnvironmentLight::sample(const Vec3& point, Vec2 u) const {
    return sample_at_surface(point, Vec3(0.0f), u);
}

LightSample EnvironmentLight::sample_at_surface(const Vec3&, const Vec3& normal, Vec2 u) const {
    LightSample ls;
    ls.is_delta = false;
    ls.distance = kInfinity;
    if (!distribution_) {
        const bool receiver = normal != Vec3(0.0f);
        if (receiver) {
            Vec3 b1, b2;
            orthonormal_basis(normal, b1, b2);
            const Vec3 local = sample_cosine_hemisphere(u);
            ls.direction = b1 * local.x + b2 * local.y + normal * local.z;
        } else {
            ls.direction = sample_uniform_sphere(u);
        }
        ls.pdf = pdf_direction(ls.direction, normal);
        ls.radiance = background_.color();
        return ls;
    }
    float uv_pdf = 0.0f;
    const Vec2 uv = distribution_->sample(u, &uv_pdf);
    const std::optional<Vec3> direction = background_.direction_of(uv);
    const float jacobian = solid_angle_per_uv(uv);
    if (!direction || !(jacobian > 0.0f) || !(uv_pdf > 0.0f)) return ls;
    ls.direction = *direction;
    ls.pdf = uv_pdf / jacobian;
    ls.radiance = background_.evaluate(ls.direction);
    return ls;
}

float EnvironmentLight::pdf_direction(const Vec3& direction, const Vec3& normal) const {
    if (!distribution_)
        return normal != Vec3(0.0f) ? cosine_hemisphere_pdf(dot(normalize(direction), normal)) : uniform_sphere_pdf();
    const Vec2 uv = background_.uv_of(direction);
    const float jacobian = solid_angle_per_uv(uv);
    return jacobian > 0.0f ? distribution_->pdf(uv) / jacobian : 0.0f;
}

}  // namespace glint
