#pragma once
/// \file Filtered lookups into an Image, shared by textures and environment maps.

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"

namespace glint {

/// What a lookup does outside [0, 1).
enum class WrapMode { Repeat, Clamp };

/// Bilinear interpolation of channels [first, first + count) at uv ∈ [0,1]² (v = 0 is the
/// top row; texel centres at half-integer pixel coordinates), wrapping u and v separately.
void sample_bilinear(const Image& image, const Vec2& uv, WrapMode wrap_u, WrapMode wrap_v, int first, int count,
                     float* out);

/// The colour at uv, bilinear as sample_bilinear: channels 0-2 of an image with three or
/// more channels, channel 0 as grey for one or two (grey, grey + alpha).
[[nodiscard]] Color sample_bilinear_color(const Image& image, const Vec2& uv, WrapMode wrap_u, WrapMode wrap_v);

}  // namespace glint
