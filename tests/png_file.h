#pragma once
// 8- and 16-bit PNG files written byte for byte by tests, with no library's colour or alpha
// handling on the way: the samples a test gives are the samples the file holds (zlib "stored" blocks,
// RFC 1950/1951; chunks and CRC-32 as the PNG specification, ISO/IEC 15948, defines them).

#include "test_files.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glint_test {

namespace png_detail {

inline uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xFFFFFFFFu;
    for (const char ch : bytes) {
        crc ^= static_cast<unsigned char>(ch);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

inline std::string big_endian(uint32_t v) {
    return {char(v >> 24), char((v >> 16) & 0xFF), char((v >> 8) & 0xFF), char(v & 0xFF)};
}

inline std::string chunk(const std::string& type, const std::string& data) {
    return big_endian(uint32_t(data.size())) + type + data + big_endian(crc32(type + data));
}

/// `raw` as a zlib stream of uncompressed blocks.
inline std::string zlib_stored(const std::string& raw) {
    std::string out = "\x78\x01";
    uint32_t a = 1, b = 0;  // Adler-32
    for (const char ch : raw) {
        a = (a + static_cast<unsigned char>(ch)) % 65521u;
        b = (b + a) % 65521u;
    }
    std::size_t at = 0;
    do {
        const std::size_t n = std::min<std::size_t>(raw.size() - at, 65535);
        const bool last = at + n == raw.size();
        out += char(last ? 1 : 0);
        out += {char(n & 0xFF), char(n >> 8), char(~n & 0xFF), char((~n >> 8) & 0xFF)};
        out += raw.substr(at, n);
        at += n;
    } while (at < raw.size());
    return out + big_endian((b << 16) | a);
}

/// A PNG of `bit_depth` 8 or 16 whose rows (from the top, filter bytes not included) are `rows_bytes`.
inline std::string write_png(const std::filesystem::path& path, int width, int height, int channels, int bit_depth,
                             const std::string& rows_bytes) {
    const char color_type[5] = {0, 0, 4, 2, 6};
    std::string header = big_endian(uint32_t(width)) + big_endian(uint32_t(height));
    header += {char(bit_depth), color_type[channels], char(0), char(0), char(0)};
    std::string raw;
    const std::size_t row = rows_bytes.size() / std::size_t(height);
    for (int y = 0; y < height; ++y) {
        raw += char(0);  // filter: none
        raw.append(rows_bytes, std::size_t(y) * row, row);
    }
    const std::string bytes = std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) +
                              chunk("IDAT", zlib_stored(raw)) + chunk("IEND", "");
    write_file(path, bytes);
    return bytes;
}

}  // namespace png_detail

/// Write `samples` (row by row from the top, `channels` per pixel: 1 grey, 2 grey + alpha,
/// 3 RGB, 4 RGBA with straight alpha) as an 8-bit PNG; returns the file's bytes.
inline std::string write_png8(const std::filesystem::path& path, int width, int height, int channels,
                              const std::vector<unsigned char>& samples) {
    return png_detail::write_png(path, width, height, channels, 8,
                                 std::string(reinterpret_cast<const char*>(samples.data()), samples.size()));
}

/// The same at 16 bits per sample (stored big-endian, as PNG stores them).
inline std::string write_png16(const std::filesystem::path& path, int width, int height, int channels,
                               const std::vector<uint16_t>& samples) {
    std::string bytes;
    for (const uint16_t v : samples) bytes += {char(v >> 8), char(v & 0xFF)};
    return png_detail::write_png(path, width, height, channels, 16, bytes);
}

}  // namespace glint_test
