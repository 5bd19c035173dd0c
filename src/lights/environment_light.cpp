#include "glint/lights/environment_light.h"

#include "glint/math/constants.h"
#include "glint/math/frame.h"
#include "glint/sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

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

/// The sampling weight of each pixel: the mean of the bilinear lookup over the pixel (the
/// tent filter integrated over a pixel weighs its own texel 3/4 and each neighbour 1/8 per
/// axis; where the lookup wraps, an equirect map's longitude, so does this, elsewhere it
/// clamps) times the layout's dω/(du dv) at its centre. Row by row in parallel: built
/// serially, the sky's table was a quarter of the 85 ms of a 1×1 render lit by a 1k sky,
/// most of it first touches of fresh pages (`perf record`).
std::vector<float> pixel_weights(const Image& image, BackgroundKind kind) {
    const int w = image.width, h = image.height;
    const bool wrap_x = kind == BackgroundKind::Equirectangular;
    auto column = [&](int x) { return wrap_x ? (x + w) % w : std::clamp(x, 0, w - 1); };
    const auto at = [w](int x, int y) { return std::size_t(y) * std::size_t(w) + std::size_t(x); };
    // The horizontal pass reads its row's luminance from a row of its own; the vertical
    // pass needs the rows above and below, so the horizontal result is kept whole.
    std::vector<float> across(std::size_t(w) * std::size_t(h)), weights(across.size());
    tbb::parallel_for(0, h, [&](int y) {
        std::vector<float> luminance(static_cast<std::size_t>(w));
        for (int x = 0; x < w; ++x) luminance[std::size_t(x)] = pixel_luminance(image, x, y);
        for (int x = 0; x < w; ++x)
            across[at(x, y)] = 0.75f * luminance[std::size_t(x)] +
                               0.125f * (luminance[std::size_t(column(x - 1))] + luminance[std::size_t(column(x + 1))]);
    });
    tbb::parallel_for(0, h, [&](int y) {
        const int above = std::max(y - 1, 0), below = std::min(y + 1, h - 1);
        for (int x = 0; x < w; ++x) {
            const Vec2 centre((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h));
            weights[at(x, y)] = (0.75f * across[at(x, y)] + 0.125f * (across[at(x, above)] + across[at(x, below)])) *
                                layout_solid_angle_per_uv(kind, centre);
        }
    });
    return weights;
}

}  // namespace

std::unique_ptr<EnvironmentLight> EnvironmentLight::of(const Background& background) {
    const Image* image = background.image();
    if (background.kind() == BackgroundKind::Constant || !image) {
        if (background.color().is_black()) return nullptr;
        return std::unique_ptr<EnvironmentLight>(new EnvironmentLight(background, std::nullopt));
    }
    if (!(background.scale() > 0.0f)) return nullptr;
    const std::vector<float> weights = pixel_weights(*image, background.kind());
    const bool any = std::any_of(weights.begin(), weights.end(), [](float w) { return w > 0.0f; });
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
