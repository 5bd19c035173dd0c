#include "glint/sampling/discrete_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace glint {

namespace {

// The largest float below 1: where a u of 1 (or more) is clamped, and the ceiling of
// `u_remapped`, which callers feed into warps that expect [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

}  // namespace

DiscreteDistribution::DiscreteDistribution(std::vector<float> weights) : weights_(std::move(weights)) {
    if (weights_.empty()) throw std::invalid_argument("DiscreteDistribution: no weights");
    cdf_.resize(weights_.size() + 1);
    cdf_[0] = 0.0;
    for (std::size_t i = 0; i < weights_.size(); ++i) {
        const float w = weights_[i];
        if (!std::isfinite(w) || w < 0.0f) {
            throw std::invalid_argument("DiscreteDistribution: weight " + std::to_string(i) + " is " +
                                        std::to_string(w) + "; weights must be finite and non-negative");
        }
        cdf_[i + 1] = cdf_[i] + static_cast<double>(w);
    }
    total_ = cdf_.back();
    if (total_ == 0.0) throw std::invalid_argument("DiscreteDistribution: all weights are zero");
    // x / x is exactly 1 in IEEE arithmetic, so cdf_[n] = 1 and trailing zero-weight entries,
    // whose prefix sums equal the total, also sit at exactly 1.
    for (double& c : cdf_) c /= total_;
}

float DiscreteDistribution::pmf(std::size_t i) const {
    return static_cast<float>(static_cast<double>(weights_[i]) / total_);
}

std::size_t DiscreteDistribution::sample(float u, float* pmf_out, float* u_remapped) const {
    // `!(u > 0)` also catches NaN.
    const double uu = !(u > 0.0f) ? 0.0 : static_cast<double>(std::min(u, kOneMinusEpsilon));
    // upper_bound finds the first CDF value > u, so i is the last entry with cdf_[i] ≤ u:
    // then cdf_[i] ≤ u < cdf_[i+1], an interval that is empty for a zero weight. Since
    // cdf_[0] = 0 ≤ u and u < 1 = cdf_[n], i is in [0, n).
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), uu);
    const std::size_t i = static_cast<std::size_t>(it - cdf_.begin()) - 1;
    if (pmf_out) *pmf_out = pmf(i);
    if (u_remapped) {
        const double r = (uu - cdf_[i]) / (cdf_[i + 1] - cdf_[i]);
        *u_remapped = std::min(static_cast<float>(r), kOneMinusEpsilon);
    }
    return i;
}

}  // namespace glint
