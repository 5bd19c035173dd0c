#include "png_chunks.h"

#include "glint/image/image_io.h"
#include "glint/util/byte_order.h"

#include <cstring>

namespace glint {

void check_png_chunks(uint64_t total_size, const ByteRangeReader& read, const std::string& name) {
    unsigned char head[8] = {};
    if (!read(0, head, 8) || std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) != 0) return;
    auto fail = [&](const std::string& what) { throw ImageError(name + ": cannot read image: " + what); };
    for (uint64_t offset = 8, chunk = 0;; ++chunk) {
        // Length, type, and for IHDR its width and height: 16 bytes when the file has them.
        unsigned char h[16] = {};
        if (offset + 12 > total_size || !read(offset, h, offset + 16 <= total_size ? 16 : 8))
            fail("truncated PNG (the data ends after " + std::to_string(total_size) + " bytes, before its IEND chunk)");
        const uint64_t length = big_endian_u32(h);
        const std::string type(reinterpret_cast<const char*>(h + 4), 4);
        if (offset + 12 + length > total_size)
            fail("truncated PNG (chunk " + type + " of " + std::to_string(length) + " bytes runs past the end)");
        if (chunk == 0 && type != "IHDR") fail("malformed PNG (the first chunk is not IHDR)");
        if (type == "IHDR") {
            const uint32_t width = big_endian_u32(h + 8),
                           height = offset + 16 <= total_size ? big_endian_u32(h + 12) : 0;
            if (length < 13 || width == 0 || height == 0 || width > 1000000 || height > 1000000)
                fail("PNG header gives " + std::to_string(width) + "×" + std::to_string(height) +
                     " pixels (expected 1 to 1000000 a side)");
        }
        if (type == "IEND") return;
        offset += 12 + length;
    }
}

}  // namespace glint
