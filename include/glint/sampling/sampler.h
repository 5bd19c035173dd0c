#pragma once
/// \file The sample generator in every trace: stratified, deterministic per (seed, pixel,
/// sample index), whatever the thread count or tile order.

#include "glint/math/divisor.h"
#include "glint/math/vec2.h"

#include <cstdint>
#include <pcg_random.hpp>
#include <span>

namespace glint {

/// Padded stratified sampling (pbrt-v4's `StratifiedSampler`, after Kollig & Keller 2002):
/// the n² samples of a pixel are stratified in every dimension separately, each dimension
/// with its own random permutation of the strata, so that consecutive dimensions do not
/// correlate. Dimension 0 is the pixel plane: sample k lies in cell (k mod n, k div n) of an
/// n×n grid, jittered from the pixel's PCG32 stream exactly as Glint's first tracer did,
/// which keeps the Whitted reference images bit-identical.
///
/// Every value is a pure function of (seed, pixel, sample index, dimension): no state is
/// shared between pixels, so images do not depend on the thread schedule.
class Sampler {
public:
    /// `samples_per_axis` = n of the n×n samples per pixel (at least 1).
    Sampler(uint64_t seed, uint32_t samples_per_axis);

    /// Begin sample `index` (0 … n²−1) of the pixel with linear index `pixel`.
    void start_pixel_sample(uint64_t pixel, uint32_t index) {
        index_ = index;
        dimension_ = 0;
        // The pixel's PCG32 stream drew two numbers per sample in order: jump to this sample's
        // pair unless it is the next one anyway. The pixel's hash, only for another pixel.
        if (pixel != hashed_pixel_) {
            pixel_hash_ = hash_pixel(pixel);
            hashed_pixel_ = pixel;
        }
        if (pixel != stream_pixel_ || index != stream_next_index_) {
            stream_ = pcg32(seed_, pixel);
            stream_.advance(2ull * index);
            stream_pixel_ = pixel;
        }
        stream_next_index_ = index + 1;
        const float ux = float(stream_() >> 8) * 0x1p-24f;
        const float uy = float(stream_() >> 8) * 0x1p-24f;
        pixel_2d_ = {by_n_.divide(float(by_n_.remainder(index)) + ux), by_n_.divide(float(by_n_.quotient(index)) + uy)};
    }

    /// Position inside the pixel in [0,1)²: the current sample's jittered n×n cell.
    [[nodiscard]] Vec2 pixel_2d() const { return pixel_2d_; }
    /// Next dimension: one of the n² strata of [0,1), permuted per (pixel, dimension).
    [[nodiscard]] float next_1d();
    /// Next dimension: one of the n×n cells of [0,1)², permuted per (pixel, dimension).
    [[nodiscard]] Vec2 next_2d();
    /// Next dimension as a set of `out.size()` points stratified among themselves
    /// (correlated multi-jittered: Kensler 2013), for N light samples at one shading point.
    void next_2d_set(std::span<Vec2> out);

    [[nodiscard]] uint32_t samples_per_axis() const { return by_n_.value(); }

private:
    /// The hash of (seed, pixel) that every dimension's hash starts from.
    [[nodiscard]] uint64_t hash_pixel(uint64_t pixel) const;
    [[nodiscard]] uint64_t dimension_hash(uint32_t dimension) const;

    uint64_t seed_;
    /// The seed's part of every hash, and the pixel's: hashed once, not on every draw.
    uint64_t seed_hash_;
    /// n, and the n² strata: each divides every draw.
    Divisor by_n_, by_strata_;
    /// hash_pixel(hashed_pixel_).
    uint64_t pixel_hash_;
    uint64_t hashed_pixel_ = 0;
    uint32_t index_ = 0;
    uint32_t dimension_ = 0;
    Vec2 pixel_2d_;
    /// The pixel dimension's PCG32 stream, kept between consecutive samples of one pixel so
    /// that the common in-order walk costs two draws, not a seek (pcg32::advance).
    pcg32 stream_;
    uint64_t stream_pixel_ = ~uint64_t(0);
    uint32_t stream_next_index_ = 0;
};

/// Kensler's hash-based permutation: element `i` of a pseudo-random permutation of
/// 0 … l−1 chosen by `pattern` ("Correlated Multi-Jittered Sampling", Pixar TM 13-01, 2013).
[[nodiscard]] uint32_t permutation_element(uint32_t i, uint32_t l, uint32_t pattern);

/// Sample `s` of `count` correlated multi-jittered points in [0,1)² for `pattern`: both
/// 1-D projections are stratified into `count` strata, and the points lie one per cell of
/// an m×(count/m) grid (Kensler 2013, Listing 6).
[[nodiscard]] Vec2 correlated_multi_jitter(uint32_t s, uint32_t count, uint32_t pattern);

}  // namespace glint
