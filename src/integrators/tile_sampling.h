#pragma once
/// \file The order in which the pixels of a tile take their samples: all n² in turn, or
/// adaptively (integrators/adaptive_sampling.h), neighbours of a row together so that camera
/// rays can go as packets. Internal to integrator.cpp.
///
/// The loops take their samples through `take(lanes, then)`: it takes the samples `lanes` (at
/// most RayPacket::kSize; as one packet or one by one, as the caller chooses) and hands each
/// one's radiance to `then(x, y, radiance)`.

#include "glint/accel/ray_packet.h"
#include "glint/integrators/adaptive_sampling.h"
#include "glint/integrators/integrator.h"
#include "glint/integrators/tile_grid.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace glint::tile_sampling {

/// Pixel (x, y)'s index among the pixels of the tile `b`, row by row.
inline std::size_t tile_pixel(const TileGrid::Bounds& b, uint32_t x, uint32_t y) {
    return std::size_t(y - b.y0) * (b.x1 - b.x0) + (x - b.x0);
}

/// Up to `group` pixels of row y from x on (before x1), each taking sample `index`.
inline std::span<const PixelSample> row_lanes(std::array<PixelSample, RayPacket::kSize>& lanes, uint32_t x, uint32_t x1,
                                              uint32_t y, uint32_t group, uint32_t index) {
    const uint32_t count = std::min(group, x1 - x);
    for (uint32_t k = 0; k < count; ++k) lanes[k] = {x + k, y, index};
    return {lanes.data(), count};
}

/// Every pixel of the tile `b` takes its n² samples in order, `group` neighbours of a row
/// together.
template <class Take>
void sample_uniformly(const TileGrid::Bounds& b, uint32_t n, uint32_t group, const Take& take) {
    std::array<PixelSample, RayPacket::kSize> lanes;
    for (uint32_t y = b.y0; y < b.y1; ++y)
        for (uint32_t x = b.x0; x < b.x1; x += group)
            for (uint32_t index = 0; index < n * n; ++index)
                take(row_lanes(lanes, x, b.x1, y, group, index), [](uint32_t, uint32_t, const Color&) {});
}

/// Every pixel of the tile `b` takes its first batch of `adaptive.min_spp` samples, in the
/// progressive order of an n×n grid, `group` neighbours of a row together. The statistics
/// per pixel, row by row.
template <class Take>
std::vector<PixelError> first_batches(const TileGrid::Bounds& b, const AdaptiveSampling& adaptive, uint32_t n,
                                      uint32_t group, const Take& take) {
    std::vector<PixelError> errors(std::size_t(b.x1 - b.x0) * (b.y1 - b.y0));
    std::array<PixelSample, RayPacket::kSize> lanes;
    for (uint32_t y = b.y0; y < b.y1; ++y)
        for (uint32_t x = b.x0; x < b.x1; x += group)
            for (uint32_t k = 0; k < adaptive.min_spp; ++k)
                take(row_lanes(lanes, x, b.x1, y, group, progressive_cell(k, n)),
                     [&](uint32_t px, uint32_t py, const Color& radiance) {
                         errors[tile_pixel(b, px, py)].add(radiance.luminance());
                     });
    return errors;
}

/// The samples pixel (x, y) of tile `b` takes at least: from the largest contrast between its
/// first-batch mean luminance and its neighbours' in the tile (`errors` from first_batches).
inline uint32_t tile_minimum_samples(const TileGrid::Bounds& b, const std::vector<PixelError>& errors,
                                     const AdaptiveSampling& adaptive, uint32_t spp, uint32_t x, uint32_t y) {
    const float own = errors[tile_pixel(b, x, y)].mean();
    float largest = 0.0f;
    for (uint32_t ny = std::max(y, b.y0 + 1) - 1; ny <= std::min(y + 1, b.y1 - 1); ++ny)
        for (uint32_t nx = std::max(x, b.x0 + 1) - 1; nx <= std::min(x + 1, b.x1 - 1); ++nx)
            largest = std::max(largest, contrast(own, errors[tile_pixel(b, nx, ny)].mean()));
    return minimum_samples(adaptive, largest, spp);
}

/// Adaptive sampling of the tile `b` (integrators/adaptive_sampling.h): every pixel takes its
/// first batch; then, knowing its neighbours' first batches, every pixel not yet converged
/// takes its next sample, round after round, `group` of them together. Each pixel takes
/// the samples, in the order, that it would alone.
template <class Take>
void sample_adaptively(const TileGrid::Bounds& b, const AdaptiveSampling& adaptive, uint32_t n, uint32_t group,
                       const Take& take) {
    const uint32_t width = b.x1 - b.x0;
    std::vector<PixelError> errors = first_batches(b, adaptive, n, group, take);
    // The minimums come from the first batches, before any pixel adds to its statistics.
    std::vector<uint32_t> minimums(errors.size());
    for (uint32_t y = b.y0; y < b.y1; ++y)
        for (uint32_t x = b.x0; x < b.x1; ++x)
            minimums[tile_pixel(b, x, y)] = tile_minimum_samples(b, errors, adaptive, n * n, x, y);
    auto still_sampling = [&](uint32_t i) { return !converged(adaptive, errors[i], minimums[i]); };
    std::vector<uint32_t> active;  // row by row
    for (uint32_t i = 0; i < errors.size(); ++i)
        if (still_sampling(i)) active.push_back(i);
    std::array<PixelSample, RayPacket::kSize> lanes;
    for (uint32_t k = adaptive.min_spp; k < n * n && !active.empty(); ++k) {
        const uint32_t index = progressive_cell(k, n);
        for (std::size_t first = 0; first < active.size(); first += group) {
            const auto count = uint32_t(std::min<std::size_t>(group, active.size() - first));
            for (uint32_t j = 0; j < count; ++j)
                lanes[j] = {b.x0 + active[first + j] % width, b.y0 + active[first + j] / width, index};
            take(std::span<const PixelSample>(lanes.data(), count), [&](uint32_t x, uint32_t y, const Color& radiance) {
                errors[tile_pixel(b, x, y)].add(radiance.luminance());
            });
        }
        std::erase_if(active, [&](uint32_t i) { return !still_sampling(i); });
    }
}

}  // namespace glint::tile_sampling
