#pragma once
/// \file The film: linear radiance per pixel.

#include "glint/image/image.h"
#include "glint/math/color.h"

#include <cstdint>
#include <vector>

namespace glint {

class Film {
public:
    Film(uint32_t width, uint32_t height) : width_(width), height_(height), pixels_(std::size_t(width) * height) {}

    [[nodiscard]] uint32_t width() const { return width_; }
    [[nodiscard]] uint32_t height() const { return height_; }
    void set(uint32_t x, uint32_t y, const Color& c) { pixels_[std::size_t(y) * width_ + x] = c; }
    [[nodiscard]] const Color& at(uint32_t x, uint32_t y) const { return pixels_[std::size_t(y) * width_ + x]; }
    /// Three-channel float image of the film (linear).
    [[nodiscard]] Image to_image() const;

private:
    uint32_t width_, height_;
    std::vector<Color> pixels_;
};

}  // namespace glint
