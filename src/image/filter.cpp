#include "glint/image/filter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

/// Mitchell & Netravali, "Reconstruction Filters in Computer Graphics" (1988), eq. 8, on
/// |x| ≤ 2 with B = C = 1/3, the pair they recommend.
float mitchell_1d(float x) {
    constexpr float b = 1.0f / 3.0f, c = 1.0f / 3.0f;
    x = std::abs(x);
    if (x <= 1.0f)
        return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6.0f;
    if (x <= 2.0f)
        return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + (8 * b + 24 * c)) / 6.0f;
    return 0.0f;
}

}  // namespace

float Filter::default_radius(PixelFilter kind) {
    switch (kind) {
        case PixelFilter::Box: return 0.5f;
        case PixelFilter::Tent: return 1.0f;
        case PixelFilter::Gaussian: return 1.5f;
        case PixelFilter::Mitchell: return 2.0f;
    }
    return 0.5f;
}

namespace {

/// Indexed by PixelFilter.
constexpr std::array<std::string_view, 4> kFilterNames{"box", "tent", "gaussian", "mitchell"};

}  // namespace

std::string_view filter_name(PixelFilter kind) { return kFilterNames[std::size_t(kind)]; }

std::span<const std::string_view> filter_names() { return kFilterNames; }

std::optional<PixelFilter> filter_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kFilterNames.size(); ++i)
        if (kFilterNames[i] == name) return PixelFilter(i);
    return std::nullopt;
}

Filter::Filter(PixelFilter kind, float radius) : kind_(kind), radius_(radius == 0.0f ? default_radius(kind) : radius) {
    if (!(std::isfinite(radius_) && radius_ > 0.0f))
        throw std::invalid_argument("a pixel filter needs a positive, finite radius");
    if (kind_ != PixelFilter::Gaussian && kind_ != PixelFilter::Mitchell) return;
    // Tabulate |f| at bin centres; the sign is restored by the sample weight.
    cdf_[0] = 0.0f;
    for (int i = 0; i < kBins; ++i) {
        const float x = -radius_ + (float(i) + 0.5f) * (2.0f * radius_ / kBins);
        cdf_[i + 1] = cdf_[i] + std::abs(profile(x));
    }
    integral_ = cdf_[kBins] * (2.0f * radius_ / kBins);
    for (float& c : cdf_) c /= cdf_[kBins];
}

float Filter::profile(float x) const {
    switch (kind_) {
        case PixelFilter::Box: return std::abs(x) <= radius_ ? 1.0f : 0.0f;
        case PixelFilter::Tent: return std::max(0.0f, 1.0f - std::abs(x) / radius_);
        case PixelFilter::Gaussian: {
            // σ = r/3, shifted down so the truncated Gaussian reaches zero at the radius.
            const float sigma = radius_ / 3.0f;
            const auto g = [&](float v) { return std::exp(-v * v / (2.0f * sigma * sigma)); };
            return std::abs(x) >= radius_ ? 0.0f : g(x) - g(radius_);
        }
        case PixelFilter::Mitchell: return mitchell_1d(2.0f * x / radius_);
    }
    return 0.0f;
}

float Filter::evaluate(Vec2 offset) const { return profile(offset.x) * profile(offset.y); }

float Filter::sample_axis(float u, float& weight) const {
    const auto* upper = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const int bin = std::clamp(int(upper - cdf_.begin()) - 1, 0, kBins - 1);
    const float width = cdf_[bin + 1] - cdf_[bin];
    const float t = width > 0.0f ? (u - cdf_[bin]) / width : 0.5f;
    const float bin_size = 2.0f * radius_ / kBins;
    const float x = -radius_ + (float(bin) + std::clamp(t, 0.0f, 1.0f)) * bin_size;
    const float tabulated = std::abs(profile(-radius_ + (float(bin) + 0.5f) * bin_size));
    // f(x)/pdf(x) with pdf = |f_bin|/∫|f|: ±∫|f| up to the variation of f inside the bin.
    weight = tabulated > 0.0f ? profile(x) * integral_ / tabulated : 0.0f;
    return x;
}

FilterSample Filter::sample_tabulated(Vec2 u) const {
    float wx = 1.0f, wy = 1.0f;
    const float x = sample_axis(u.x, wx);
    const float y = sample_axis(u.y, wy);
    return {{x, y}, wx * wy};
}

}  // namespace glint
