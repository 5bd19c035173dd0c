#pragma once
/// \file Radiance pictures (.hdr, .pic: Greg Ward's RGBE format, "Real Pixels", Graphics
/// Gems II, 1991), read by Glint itself. Internal to src/image.
///
/// Most environment maps are Radiance pictures. Reading one through OpenImageIO first loads
/// its 255 libraries, 350-450 ms, several times the render of a small scene
/// (docs/performance.md, "Environment maps without OpenImageIO"); the format is a text
/// header and four bytes a pixel, run-length coded by channel, so Glint reads it here.
/// The values are byte × 2^(exponent − 136), exactly, as Bruce Walter's rgbe.c (which
/// OpenImageIO uses) converts them: OpenImageIO's floats bit for bit on every sky tested
/// (2.4.7 is one ulp off at three exponents no sky holds). EXPOSURE and GAMMA lines are
/// ignored, as there. A picture stored in another orientation than the usual "-Y height +X width" is
/// left to OpenImageIO, whose result this reader would otherwise have to reproduce.

#include "image_codec.h"

#include "glint/image/image.h"

#include <cstddef>
#include <optional>
#include <string>

namespace glint::codec {

/// Whether `bytes` begin as a Radiance picture does ("#?", then the program's name).
[[nodiscard]] bool is_radiance_picture(const unsigned char* bytes, std::size_t size);

/// Decode the Radiance picture in `bytes` into `out` (three linear channels R, G, B, straight
/// into the image's pixels). Returns "" on success and otherwise what is wrong, worded to
/// follow "NAME: "; nothing when the picture is one to read through OpenImageIO instead
/// (another orientation). `check` sees the header's size before any pixel is allocated.
[[nodiscard]] std::optional<std::string> read_radiance_picture(const unsigned char* bytes, std::size_t size,
                                                               const SizeCheck& check, Image& out);

}  // namespace glint::codec
