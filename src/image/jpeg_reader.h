#pragma once
/// \file JPEG files read by Glint itself through libjpeg. Internal to src/image.
///
/// glTF assets embed JPEG textures (two of the Khronos samples in ../shared/data do), and
/// reading one through OpenImageIO first loads its 255 libraries, some 400 ms, longer than a
/// small render (docs/performance.md, "JPEG textures without OpenImageIO"). OpenImageIO reads
/// JPEG with libjpeg at its default settings, asking for RGB or grey output; this reader asks
/// libjpeg for the same and converts the values the same way, so that its result is
/// OpenImageIO's bit for bit (JpegReader.* compares them). CMYK and YCCK files, and any file
/// libjpeg refuses or warns about (a file cut short, corrupt data), are left to OpenImageIO,
/// which reads them, or words their error, as before.

#include "image_codec.h"

#include <cstddef>
#include <optional>
#include <string>

namespace glint::codec {

/// Whether `bytes` begin with a JPEG's start-of-image marker and the next marker's lead byte.
[[nodiscard]] bool is_jpeg(const unsigned char* bytes, std::size_t size);

/// Decode the JPEG in `bytes` into `out` as OpenImageIO would. Returns "" on success or
/// `check`'s refusal of the header's size (checked before libjpeg allocates for the
/// pixels); nothing when the file is one to read through OpenImageIO instead.
[[nodiscard]] std::optional<std::string> read_jpeg(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                                   DecodedImage& out);

}  // namespace glint::codec
