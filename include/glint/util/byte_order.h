#pragma once
/// \file Unsigned integers as a file format stores them, read and written byte by byte, so
/// that the value depends neither on the machine's byte order nor on the address's alignment.

#include <array>
#include <cstdint>

namespace glint {

/// BMP and GLB store their integers least significant byte first.
[[nodiscard]] inline uint32_t little_endian_u16(const unsigned char* b) { return uint32_t(b[0]) | uint32_t(b[1]) << 8; }
[[nodiscard]] inline uint32_t little_endian_u32(const unsigned char* b) {
    return little_endian_u16(b) | little_endian_u16(b + 2) << 16;
}

/// PNG stores its integers most significant byte first ("network byte order").
[[nodiscard]] inline uint32_t big_endian_u32(const unsigned char* b) {
    return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}
[[nodiscard]] inline std::array<unsigned char, 4> big_endian_bytes(uint32_t v) {
    return {static_cast<unsigned char>(v >> 24), static_cast<unsigned char>(v >> 16),
            static_cast<unsigned char>(v >> 8), static_cast<unsigned char>(v)};
}

}  // namespace glint
