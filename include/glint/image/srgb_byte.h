#pragma once
/// \file Linear values to the 8-bit sRGB levels of a PNG.

#include <cstdint>

namespace glint {

/// The nearest of 256 levels to a display value in [0, 1], as OpenImageIO quantises; NaN
/// and values below 0 as 0, above 1 as 255.
[[nodiscard]] uint8_t display_byte(float display);

/// `display_byte(linear_to_srgb(linear))`, exactly, without its `powf`: the level is the
/// number of the 255 linear thresholds at which it steps up that `linear` has reached,
/// found by a binary search (8 comparisons). The thresholds are found once, by bisecting
/// the float values for each step of the function itself, which rises with its argument.
/// 3 times faster than the `powf` (a 640×480 render's display transform: 8 ms → 2.5 ms
/// on two threads).
[[nodiscard]] uint8_t srgb_byte(float linear);

}  // namespace glint
