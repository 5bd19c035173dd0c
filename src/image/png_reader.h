#pragma once
/// \file PNG files read by Glint itself through libpng. Internal to src/image.
///
/// Reading a PNG texture through OpenImageIO first loads its 255 libraries, 350-450 ms,
/// more than the render of a small scene (docs/performance.md, "PNG textures without
/// OpenImageIO"). OpenImageIO reads PNG with libpng, asking it to expand palettes, low bit
/// depths and tRNS transparency to whole channels of 8 or 16 bits; this reader asks libpng
/// for the same and converts the values the same way, so that its result is OpenImageIO's
/// bit for bit (PngReader.* compares them on every colour type and bit depth). A file whose
/// header carries what this reader does not reproduce (an oFFs offset, "glint:" text) or
/// that libpng refuses is left to OpenImageIO, which reads it, or words its error, as before.

#include "image_codec.h"

#include <cstddef>
#include <optional>
#include <string>

namespace glint::codec {

/// Whether `bytes` begin with the PNG signature.
[[nodiscard]] bool is_png(const unsigned char* bytes, std::size_t size);

/// Decode the PNG in `bytes` into `out` as OpenImageIO would (straight alpha). Returns ""
/// on success or `check`'s refusal of the header's size (checked before any pixel is
/// allocated); nothing when the file is one to read through OpenImageIO instead.
[[nodiscard]] std::optional<std::string> read_png(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                                  DecodedImage& out);

}  // namespace glint::codec
