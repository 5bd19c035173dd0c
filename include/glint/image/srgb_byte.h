#pragma once
/// \file Linear values to the 8-bit sRGB levels of a PNG.

#include <cstdint>

namespace glint {

/// The nearest of 256 levels to a display value in [0, 1], as OpenImageIO quantises; NaN
/// and values below 0 as 0, above 1 as 255.
[[nodiscard]] uint8_t display_byte(float display);

/// `display_byte(linear_to_srgb(linear))`, exactly, without its `powf`: the level is the
/// number of the 255 linear thresholds at which it steps up that `linear` has reached. The
/// thresholds are found once, by bisecting the float values for each step of the function
/// itself, which rises with its argument. A table by the float's top 16 bits gives the level
/// where its bucket starts, and one comparison the step that may lie inside the bucket.
/// (921,600 values of random levels, a 640×480 RGB image, on one thread: 39 ms by a binary
/// search among the thresholds, whose branches such values mispredict, 2.0 ms by the table;
/// docs/performance.md.)
[[nodiscard]] uint8_t srgb_byte(float linear);

}  // namespace glint
