#pragma once
/// \file A BMP's header, checked before OpenImageIO sees it. Internal to src/image.

#include "byte_range_reader.h"

#include <cstdint>
#include <string>

namespace glint {

/// OpenImageIO 2.4's BMP reader trusts the header's pairing of compression and bits per
/// pixel: a 24-bit file that claims RLE4 compression made it read through a wild pointer
/// (found by fuzz/fuzz_image, regressions/fuzz_image/bmp_rle4_compression_with_24_bits_oiio_segv).
/// So a BMP's header is read first: it must be whole, have one plane, a non-zero size, pixel
/// data that starts inside the file, and one of the pairings the format defines (none: 1, 4,
/// 8, 16, 24 or 32 bits; RLE8: 8; RLE4: 4; bit fields: 16 or 32). Throws ImageError naming
/// `name`; returns at once for data that does not start as a BMP ("BM").
void check_bmp_header(uint64_t total_size, const ByteRangeReader& read, const std::string& name);

}  // namespace glint
