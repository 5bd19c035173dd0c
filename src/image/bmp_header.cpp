#include "bmp_header.h"

#include "glint/image/image_io.h"
#include "glint/util/byte_order.h"

#include <array>

namespace glint {

namespace {

bool defined_pairing(uint32_t compression, uint32_t bits) {
    switch (compression) {
        case 0:
            return bits == 1 || bits == 4 || bits == 8 || bits == 16 || bits == 24 || bits == 32;  // BI_RGB
        case 1:
            return bits == 8;  // BI_RLE8
        case 2:
            return bits == 4;  // BI_RLE4
        case 3:
            return bits == 16 || bits == 32;  // BI_BITFIELDS
        default:
            return false;
    }
}

}  // namespace

void check_bmp_header(uint64_t total_size, const ByteRangeReader& read, const std::string& name) {
    // The file header (14 bytes) and the first 20 bytes of the info header: its size, the
    // image's size, planes and bits per pixel (as OS/2's 12-byte header has them too), and
    // for the longer headers the compression.
    std::array<unsigned char, 34> h{};
    if (total_size < 2 || !read(0, h.data(), 2) || h[0] != 'B' || h[1] != 'M') return;
    auto fail = [&](const std::string& what) { throw ImageError(name + ": cannot read image: BMP " + what); };
    if (total_size < 26 || !read(0, h.data(), 26)) fail("header is truncated");
    const uint32_t info_size = little_endian_u32(h.data() + 14), data_offset = little_endian_u32(h.data() + 10);
    const bool core = info_size == 12;  // OS/2 1.x: 16-bit sizes, no compression field
    if (!core && info_size < 40)
        fail("info header of " + std::to_string(info_size) + " bytes is not one the format defines");
    if (!core && (total_size < 34 || !read(0, h.data(), 34))) fail("header is truncated");
    const int64_t width =
        core ? int64_t(little_endian_u16(h.data() + 18)) : int64_t(int32_t(little_endian_u32(h.data() + 18)));
    const int64_t height =
        core ? int64_t(little_endian_u16(h.data() + 20)) : int64_t(int32_t(little_endian_u32(h.data() + 22)));
    const uint32_t planes = little_endian_u16(h.data() + (core ? 22 : 26)),
                   bits = little_endian_u16(h.data() + (core ? 24 : 28));
    const uint32_t compression = core ? 0 : little_endian_u32(h.data() + 30);
    if (width <= 0 || height == 0)
        fail("header gives " + std::to_string(width) + "×" + std::to_string(height) + " pixels");
    if (planes != 1) fail("header gives " + std::to_string(planes) + " planes; expected 1");
    if (!defined_pairing(compression, bits))
        fail("header pairs compression " + std::to_string(compression) + " with " + std::to_string(bits) +
             " bits per pixel, which the format does not define");
    const uint64_t headers_end = 14 + uint64_t(info_size);
    if (data_offset < headers_end || data_offset >= total_size)
        fail("pixel data offset " + std::to_string(data_offset) + " is not between the headers' end (" +
             std::to_string(headers_end) + ") and the file's (" + std::to_string(total_size) + ")");
}

}  // namespace glint
