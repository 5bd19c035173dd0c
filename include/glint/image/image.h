#pragma once
/// \file In-memory float image.

#include "glint/math/color.h"

#include <cstddef>
#include <string>
#include <vector>

namespace glint {

/// Linear float pixels, row by row from the top, `channels` interleaved floats per pixel.
struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;
    /// One name per channel ("R", "G", "B", "albedo.R", "Z", ...) for the formats that keep
    /// names (EXR); empty for R, G, B (and A).
    std::vector<std::string> channel_names;

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, 0.0f) {}

    [[nodiscard]] bool empty() const { return pixels.empty(); }
    [[nodiscard]] float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
    [[nodiscard]] float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
    /// RGB of a pixel: grey images repeat their single channel.
    [[nodiscard]] Color rgb(int x, int y) const {
        const float* p = &pixels[(std::size_t(y) * width + x) * channels];
        return channels >= 3 ? Color(p[0], p[1], p[2]) : Color(p[0]);
    }
};

}  // namespace glint
