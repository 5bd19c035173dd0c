#pragma once
/// \file In-memory float image.

#include "glint/math/color.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace glint {

/// Where an image lies in a larger frame: an OpenEXR data window inside its display window.
/// A crop of a render (--crop) is written with it; `glint assemble` joins crops by it.
struct FrameRegion {
    /// The image's top-left pixel in the frame.
    int x = 0, y = 0;
    /// The frame's size; 0 when the image is the whole frame.
    int frame_width = 0, frame_height = 0;

    [[nodiscard]] bool whole() const { return frame_width == 0; }
    bool operator==(const FrameRegion&) const = default;
};

/// Linear float pixels, row by row from the top, `channels` interleaved floats per pixel.
struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;
    /// One name per channel ("R", "G", "B", "albedo.R", "Z", ...) for the formats that keep
    /// names (EXR); empty for R, G, B (and A).
    std::vector<std::string> channel_names;
    /// Where the pixels lie in the frame (EXR keeps it; other formats hold the pixels alone).
    FrameRegion region;
    /// Text the file's header keeps beside the pixels (EXR only, stored as "glint:NAME"): what
    /// rendered it, so that `glint assemble` joins only crops of one render.
    std::vector<std::pair<std::string, std::string>> attributes;

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
