#include "glint/integrators/tile_grid.h"

#include <algorithm>

namespace glint {

TileGrid::TileGrid(uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      tiles_x_((width + kTileSize - 1) / kTileSize),
      tiles_y_((height + kTileSize - 1) / kTileSize),
      done_(std::make_unique<std::atomic<bool>[]>(std::size_t(tiles_x_) * tiles_y_)) {}

TileGrid::Bounds TileGrid::bounds(uint32_t tile) const {
    const uint32_t x0 = (tile % tiles_x_) * kTileSize, y0 = (tile / tiles_x_) * kTileSize;
    return {x0, y0, std::min(x0 + kTileSize, width_), std::min(y0 + kTileSize, height_)};
}

uint32_t TileGrid::done_count() const {
    uint32_t n = 0;
    for (uint32_t t = 0; t < count(); ++t) n += done(t) ? 1 : 0;
    return n;
}

std::vector<uint32_t> TileGrid::tiles_overlapping(const std::optional<PixelRect>& crop) const {
    std::vector<uint32_t> tiles;
    for (uint32_t t = 0; t < count(); ++t) {
        const Bounds b = bounds(t);
        if (!crop || crop->overlaps(PixelRect{b.x0, b.y0, b.x1, b.y1})) tiles.push_back(t);
    }
    return tiles;
}

}  // namespace glint
