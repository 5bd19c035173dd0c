#pragma once
/// \file The film: per pixel, the weighted sum of radiance samples and the sum of weights.
///
/// Accumulating sums rather than finished averages lets a render add samples in passes
/// (progressive preview) and carry filter weights (image/filter.h); a pixel's value is
/// Σ w·L / Σ w (nori's ImageBlock, pbrt-v4's RGBFilm::AddSample).

#include "glint/image/image.h"
#include "glint/math/color.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace glint {

/// What a film keeps per pixel.
struct FilmPixel {
    Color weighted_sum;
    float weight_sum = 0.0f;
    uint32_t samples = 0;
};

class Film {
public:
    Film(uint32_t width, uint32_t height) : width_(width), height_(height), pixels_(std::size_t(width) * height) {}

    [[nodiscard]] uint32_t width() const { return width_; }
    [[nodiscard]] uint32_t height() const { return height_; }

    /// Add radiance `radiance` with filter weight `weight` to pixel (x, y). A pixel is only
    /// ever written by one thread at a time (the integrator's tiles do not overlap).
    void add_sample(uint32_t x, uint32_t y, const Color& radiance, float weight) {
        FilmPixel& p = pixels_[std::size_t(y) * width_ + x];
        // One rounding, always: an explicit fused multiply-add. Left to the compiler, sum +
        // radiance·weight is fused in some inlined copies of the pixel loop and not in others,
        // and the thread count decides which copy runs, so images would depend on it.
        p.weighted_sum = Color(std::fma(radiance.r, weight, p.weighted_sum.r), std::fma(radiance.g, weight, p.weighted_sum.g),
                               std::fma(radiance.b, weight, p.weighted_sum.b));
        p.weight_sum += weight;
        ++p.samples;
    }
    /// The pixel's value: the weighted mean of its samples (black before any sample).
    [[nodiscard]] Color at(uint32_t x, uint32_t y) const;
    /// Sum of the weights that reached pixel (x, y).
    [[nodiscard]] float weight_at(uint32_t x, uint32_t y) const { return pixels_[std::size_t(y) * width_ + x].weight_sum; }
    /// Number of samples that reached pixel (x, y) (0 where an interrupted render never got).
    [[nodiscard]] uint32_t samples_at(uint32_t x, uint32_t y) const { return pixels_[std::size_t(y) * width_ + x].samples; }
    /// Three-channel float image of the pixel values (linear); with `sample_counts`, a
    /// fourth channel holds each pixel's sample count (for partial renders).
    [[nodiscard]] Image to_image(bool sample_counts = false) const;

    /// The accumulators, row by row from the top (checkpoints save and restore them).
    [[nodiscard]] std::span<const FilmPixel> pixels() const { return pixels_; }
    [[nodiscard]] std::span<FilmPixel> pixels() { return pixels_; }

private:
    uint32_t width_, height_;
    std::vector<FilmPixel> pixels_;
};

}  // namespace glint
