#pragma once
/// \file 8-bit PNG output through libpng. Internal to src/image.
///
/// The one format image_io.cpp writes without OpenImageIO: PNG is what most renders are
/// written as, and libpng costs a program 3 ms to load where OpenImageIO's module costs
/// 200 ms (image_codec.h), so a small render to PNG finishes in milliseconds. Every other
/// format, and every read, goes through OpenImageIO.

#include <cstdint>
#include <filesystem>
#include <string>

namespace glint {

/// Write `channels` (1 grey, 2 grey + alpha, 3 RGB) 8-bit display values per pixel, row by
/// row from the top, as a PNG tagged sRGB, to `file`. Returns "" or what failed ("cannot
/// write image: ...").
[[nodiscard]] std::string write_png(const std::filesystem::path& file, int width, int height, int channels,
                                    const uint8_t* values);

}  // namespace glint
