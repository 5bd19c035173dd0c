#pragma once
/// \file A rectangle of an image's pixels: a crop, a tile.

#include <cstdint>

namespace glint {

/// A rectangle of pixels [x0, x1) × [y0, y1), counted from the top left.
struct PixelRect {
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    [[nodiscard]] uint32_t width() const { return x1 - x0; }
    [[nodiscard]] uint32_t height() const { return y1 - y0; }
    [[nodiscard]] bool overlaps(const PixelRect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
    bool operator==(const PixelRect&) const = default;
};

}  // namespace glint
