#pragma once
/// \file Pixel reconstruction filters, applied by filter importance sampling.
///
/// Each camera sample is placed at an offset drawn from the filter's own distribution and
/// carries the weight f/pdf (constant for positive filters, ±const for Mitchell's negative
/// lobes); a pixel is the weighted mean of its samples. Every sample lands in exactly one
/// pixel, so no thread writes another's pixels and images stay deterministic (pbrt-v4,
/// "Filter Importance Sampling", Ernst et al. 2006).

#include "glint/integrators/render_settings.h"
#include "glint/math/vec2.h"

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>

namespace glint {

struct FilterSample {
    /// Offset from the pixel centre, in pixels.
    Vec2 offset;
    float weight = 1.0f;
};

class Filter {
public:
    /// `radius` 0 takes the filter's default. Throws std::invalid_argument for a negative
    /// or non-finite radius.
    Filter(PixelFilter kind, float radius = 0.0f);

    /// Map a stratified u in [0,1)² to an offset and its weight; strata stay contiguous.
    /// Inline: it runs once per camera sample.
    [[nodiscard]] FilterSample sample(Vec2 u) const {
        switch (kind_) {
            case PixelFilter::Box: return {{(u.x - 0.5f) * 2.0f * radius_, (u.y - 0.5f) * 2.0f * radius_}, 1.0f};
            case PixelFilter::Tent: return {{radius_ * sample_tent(u.x), radius_ * sample_tent(u.y)}, 1.0f};
            default: return sample_tabulated(u);
        }
    }
    /// The filter's value at `offset` (separable: f(x)·f(y)); zero outside the radius.
    [[nodiscard]] float evaluate(Vec2 offset) const;

    [[nodiscard]] PixelFilter kind() const { return kind_; }
    [[nodiscard]] float radius() const { return radius_; }
    [[nodiscard]] static float default_radius(PixelFilter kind);

private:
    static constexpr int kBins = 256;
    /// Map a uniform ξ in [0,1) to the tent distribution on (-1, 1) by inverting its CDF.
    [[nodiscard]] static float sample_tent(float xi) {
        return xi < 0.5f ? std::sqrt(2.0f * xi) - 1.0f : 1.0f - std::sqrt(2.0f - 2.0f * xi);
    }
    [[nodiscard]] FilterSample sample_tabulated(Vec2 u) const;
    [[nodiscard]] float profile(float x) const;
    /// Sample one axis of a tabulated filter: |f| piecewise constant in kBins bins.
    [[nodiscard]] float sample_axis(float u, float& weight) const;

    PixelFilter kind_;
    float radius_;
    /// CDF of |f| over the bins (tabulated filters only), cdf_[kBins] = 1.
    std::array<float, kBins + 1> cdf_{};
    float integral_ = 0.0f;
};

/// The filter's name as in scene files and on the command line ("box", "tent", ...).
[[nodiscard]] std::string_view filter_name(PixelFilter kind);
/// Every filter's name, in PixelFilter order: the choices of `filter` and `--filter`.
[[nodiscard]] std::span<const std::string_view> filter_names();
/// The filter called `name`, if there is one.
[[nodiscard]] std::optional<PixelFilter> filter_from_name(std::string_view name);

}  // namespace glint
