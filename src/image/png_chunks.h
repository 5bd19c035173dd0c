#pragma once
/// \file A PNG's chunk structure, checked before libpng sees it. Internal to src/image.

#include "byte_range_reader.h"

#include <cstdint>
#include <string>

namespace glint {

/// libpng prints its own "libpng error: ..." line to stderr before OpenImageIO reports a
/// truncated or malformed PNG, so a user's first line named no file. So a PNG's chunks are
/// walked first: each must fit in the `total_size` bytes, IHDR must have a size libpng
/// accepts (1 to 10⁶ pixels a side, its default limit), and IEND must be reached. Throws
/// ImageError naming `name`; returns at once for data that does not start as a PNG.
void check_png_chunks(uint64_t total_size, const ByteRangeReader& read, const std::string& name);

}  // namespace glint
