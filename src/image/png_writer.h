#pragma once
/// \file 8-bit PNG output, written over zlib. Internal to src/image.
///
/// The one format image_io.cpp writes without OpenImageIO: PNG is what most renders are
/// written as, and OpenImageIO's module costs a process 350 ms to load (image_codec.h), so
/// a small render to PNG finishes in milliseconds. libpng deflates on one thread, which on a
/// 640×480 render took as long as tracing its rays on two; so the chunks are written here
/// and the rows deflated in stripes on every thread (pigz's scheme, png_writer.cpp). Every
/// other format, and every read, goes through OpenImageIO or OpenEXR.

#include <cstdint>
#include <filesystem>
#include <string>

namespace glint {

/// Write `channels` (1 grey, 2 grey + alpha, 3 RGB) 8-bit display values per pixel, row by
/// row from the top, as a PNG tagged sRGB, to `file`. The bytes depend on the values alone,
/// never on the thread count. Returns "" or what failed ("cannot write image: ...").
[[nodiscard]] std::string write_png(const std::filesystem::path& file, int width, int height, int channels,
                                    const uint8_t* values);

}  // namespace glint
