#pragma once
/// \file Crops of a frame and the frame they make again: what `glint render --crop` writes
/// and `glint assemble` joins (pbrt-v4's --pixelbounds and `imgtool assemble`). A crop keeps
/// its place in the frame (Image::region, an EXR's data window inside its display window)
/// and what rendered it (Image::attributes), so that only crops of one render are joined.

#include "glint/image/image.h"

#include <span>
#include <string>

namespace glint {

/// The pixels [x0, x1) × [y0, y1) of `frame` (a whole frame), with their region in it and
/// the frame's channel names and attributes.
[[nodiscard]] Image crop_of(const Image& frame, int x0, int y0, int x1, int y1);

/// An image to assemble and the name messages give it (its file).
struct FramePart {
    std::string name;
    Image image;
};

/// The frame `parts` make: they must share a frame size, channel names and attributes, lie
/// inside the frame, overlap nowhere and cover every pixel. Throws ImageError naming the
/// parts at fault and what is wrong.
[[nodiscard]] Image assemble_frame(std::span<const FramePart> parts);

}  // namespace glint
