#pragma once
/// \file Adaptive anti-aliasing, in the spirit of Whitted (1980) and POV-Ray's `+AM`: a pixel
/// takes `min_spp` samples, then more in batches of `min_spp` while the estimated error of its
/// mean is above a threshold, up to the render's samples per pixel. Each pixel decides from
/// its own samples only, so the image does not depend on the thread count.
///
/// The error is the standard error of the pixel's mean luminance relative to that mean,
///
///     e = √(s²/n) / (Ȳ + 0.01),
///
/// with s² the unbiased sample variance of the samples' luminance Y; the 0.01 keeps
/// near-black pixels, whose relative error is large but invisible, from taking every sample.
/// Stopping on the samples' own spread biases the mean slightly (a pixel that happens to
/// look converged stops); the bias falls with min_spp.
///
/// Variance alone misses an edge that a pixel's first few samples all fall on one side of;
/// Whitted and POV-Ray compare neighbouring pixels instead. So after every pixel of a tile
/// has taken its first batch, a pixel whose first-batch mean luminance differs from a
/// neighbour's in the same tile by a contrast c = |Ya − Yb| / (Ya + Yb + 0.01) with
/// c/√min_spp above the threshold takes at least four batches (the next finer grid) before
/// its own error may stop it. Neighbours are looked at within the tile only, so that tiles
/// stay independent (and a resumed render equal to an uninterrupted one).
///
/// Samples are taken in an order whose every prefix of 4^k samples has one in each cell of a
/// 2^k × 2^k grid over the pixel (the bit-reversed Morton order below), so a pixel that stops
/// early is still stratified; that needs the maximum to be a power of 4.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glint {

struct AdaptiveSampling {
    /// Samples every pixel takes, and the batch size after them (≥ 1, ≤ the maximum).
    uint32_t min_spp = 4;
    /// Relative standard error a pixel must reach to stop early.
    float threshold = 0.01f;
};

/// The pixel-grid cell (row-major index into the side×side grid, side a power of 2) of the
/// k-th sample of the progressive order: k's bits de-interleaved into (x, y) and each
/// reversed, so the low bits of k, which vary first, pick the coarse position.
[[nodiscard]] inline uint32_t progressive_cell(uint32_t k, uint32_t side) {
    uint32_t bits = 0;
    while ((1u << bits) < side) ++bits;
    uint32_t x = 0, y = 0;
    for (uint32_t b = 0; b < bits; ++b) {
        x |= ((k >> (2 * b)) & 1u) << (bits - 1 - b);
        y |= ((k >> (2 * b + 1)) & 1u) << (bits - 1 - b);
    }
    return y * side + x;
}

/// True if `n` is 1, 4, 16, 64, ...
[[nodiscard]] constexpr bool is_power_of_four(uint32_t n) {
    return n != 0 && (n & (n - 1)) == 0 && (n & 0x55555555u) != 0;
}

/// Running luminance statistics of one pixel's samples (Welford's update, for a variance
/// that does not cancel).
class PixelError {
public:
    void add(float luminance) {
        ++count_;
        const double delta = luminance - mean_;
        mean_ += delta / count_;
        squares_ += delta * (luminance - mean_);
    }
    [[nodiscard]] uint32_t count() const { return count_; }
    [[nodiscard]] float mean() const { return float(mean_); }
    /// e above; infinite for fewer than two samples (no spread known yet).
    [[nodiscard]] float relative_error() const {
        if (count_ < 2) return std::numeric_limits<float>::infinity();
        const double variance_of_mean = squares_ / (count_ - 1) / count_;
        return float(std::sqrt(variance_of_mean) / (std::abs(mean_) + 0.01));
    }

private:
    uint32_t count_ = 0;
    double mean_ = 0.0, squares_ = 0.0;
};

/// The contrast c above between two mean luminances.
[[nodiscard]] inline float contrast(float a, float b) { return std::abs(a - b) / (std::abs(a) + std::abs(b) + 0.01f); }

/// The samples a pixel takes at least, of `spp` at most, given the largest contrast of its
/// first batch with its neighbours'.
[[nodiscard]] inline uint32_t minimum_samples(const AdaptiveSampling& adaptive, float max_contrast, uint32_t spp) {
    const bool edge = max_contrast / std::sqrt(float(adaptive.min_spp)) > adaptive.threshold;
    return edge ? std::min(4 * adaptive.min_spp, spp) : adaptive.min_spp;
}

/// True once a pixel that has taken `error.count()` samples, at least `minimum`, may stop: at
/// the end of a batch, with its error at or below the threshold.
[[nodiscard]] inline bool converged(const AdaptiveSampling& adaptive, const PixelError& error, uint32_t minimum) {
    return error.count() >= minimum && error.count() % adaptive.min_spp == 0 &&
           error.relative_error() <= adaptive.threshold;
}

}  // namespace glint
