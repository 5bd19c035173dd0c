#pragma once
/// \file A piecewise-constant distribution over indices: pick a triangle of an emissive mesh
/// by area, or a light by power, with probability proportional to its weight.

#include <cstddef>
#include <vector>

namespace glint {

/// Samples index i with probability w_i / Σw by inverting the CDF with a binary search
/// (pbrt-v4's `PiecewiseConstant1D` without the continuous part). Zero-weight entries get an
/// empty CDF interval and are never returned, so a caller may keep them for indexing.
class DiscreteDistribution {
public:
    /// Builds the CDF of `weights`. Throws std::invalid_argument if the list is empty, a
    /// weight is negative, NaN or infinite, or every weight is zero.
    explicit DiscreteDistribution(std::vector<float> weights);

    /// Number of entries, zero-weight ones included.
    [[nodiscard]] std::size_t size() const { return weights_.size(); }

    /// Probability of returning `i`: w_i / Σw (0 for a zero weight).
    [[nodiscard]] float pmf(std::size_t i) const;

    /// Σw, the normaliser: a light sampler's total power, a mesh's total area.
    [[nodiscard]] float total() const { return static_cast<float>(total_); }

    /// The index i with CDF(i) ≤ u < CDF(i+1), for u in [0, 1) (values outside are clamped).
    /// `pmf` receives pmf(i). `u_remapped` receives (u − CDF(i)) / pmf(i), uniform in [0, 1)
    /// and independent of i, so one random number can pick the entry and then sample it.
    [[nodiscard]] std::size_t sample(float u, float* pmf = nullptr, float* u_remapped = nullptr) const;

private:
    std::vector<float> weights_;
    // cdf_[i] = (w_0 + … + w_{i−1}) / Σw, with cdf_[0] = 0 and cdf_[n] = 1 exactly. Double,
    // because a float prefix sum over a million triangle areas drifts by more than the
    // smallest areas, and a float CDF near 1 (spacing 6e-8) merges tiny entries into their
    // neighbours. Adding a zero weight leaves the sum unchanged, so zero-weight intervals
    // are exactly empty.
    std::vector<double> cdf_;
    double total_ = 0.0;
};

}  // namespace glint
