#pragma once
/// \file The tiles a render is cut into, and which of them are finished: an interrupted
/// render saves exactly the finished ones, and a resumed render skips them.

#include "glint/integrators/pixel_rect.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace glint {

class TileGrid {
public:
    /// 16×16 pixels: small enough to balance two to many threads, large enough that a
    /// tile's rays share the cache.
    static constexpr uint32_t kTileSize = 16;

    struct Bounds {
        uint32_t x0, y0, x1, y1;  ///< pixels [x0, x1) × [y0, y1)
    };

    TileGrid(uint32_t width, uint32_t height);

    [[nodiscard]] uint32_t width() const { return width_; }
    [[nodiscard]] uint32_t height() const { return height_; }
    [[nodiscard]] uint32_t count() const { return tiles_x_ * tiles_y_; }
    [[nodiscard]] Bounds bounds(uint32_t tile) const;
    /// The tile pixel (x, y) belongs to.
    [[nodiscard]] uint32_t tile_of(uint32_t x, uint32_t y) const { return (y / kTileSize) * tiles_x_ + x / kTileSize; }
    /// Finished: every pixel of the tile has all its samples in the film.
    [[nodiscard]] bool done(uint32_t tile) const { return done_[tile].load(std::memory_order_acquire); }
    void mark_done(uint32_t tile) { done_[tile].store(true, std::memory_order_release); }
    [[nodiscard]] uint32_t done_count() const;
    /// The tiles a render of `crop` takes, in order: those it overlaps, or all without one.
    [[nodiscard]] std::vector<uint32_t> tiles_overlapping(const std::optional<PixelRect>& crop) const;

private:
    uint32_t width_, height_, tiles_x_, tiles_y_;
    std::unique_ptr<std::atomic<bool>[]> done_;
};

}  // namespace glint
