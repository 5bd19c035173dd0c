#pragma once
// Glint's own image readers against OpenImageIO's reading of the same bytes
// (png_reader_test.cpp, jpeg_reader_test.cpp): every field of the decoded image, and every
// float bit for bit.

#include "image/image_codec.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <string>

namespace glint_test {

inline std::string accept_any_image_size(int, int, int) { return ""; }

/// What OpenImageIO makes of `bytes`, given the file name `name` (its extension picks the
/// reader OpenImageIO tries first).
inline glint::codec::DecodedImage read_with_oiio(const std::string& bytes, const std::string& name) {
    glint::codec::DecodedImage decoded;
    const std::string error = glint::codec::oiio().read_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                                               bytes.size(), name, accept_any_image_size, decoded);
    EXPECT_EQ(error, "");
    return decoded;
}

inline void expect_same_decoded_image(const glint::codec::DecodedImage& plain, const glint::codec::DecodedImage& oiio) {
    EXPECT_EQ(plain.width, oiio.width);
    EXPECT_EQ(plain.height, oiio.height);
    EXPECT_EQ(plain.channels, oiio.channels);
    EXPECT_EQ(plain.channel_names, oiio.channel_names);
    EXPECT_EQ(plain.integer_data, oiio.integer_data);
    EXPECT_EQ(plain.linear_tagged, oiio.linear_tagged);
    EXPECT_EQ(plain.alpha_channel, oiio.alpha_channel);
    EXPECT_EQ(plain.x, oiio.x);
    EXPECT_EQ(plain.y, oiio.y);
    EXPECT_EQ(plain.frame_width, oiio.frame_width);
    EXPECT_EQ(plain.frame_height, oiio.frame_height);
    EXPECT_EQ(plain.attributes, oiio.attributes);
    ASSERT_EQ(plain.pixels.size(), oiio.pixels.size());
    std::size_t differing = 0, first = 0;
    for (std::size_t i = plain.pixels.size(); i-- > 0;)
        if (std::bit_cast<uint32_t>(plain.pixels[i]) != std::bit_cast<uint32_t>(oiio.pixels[i])) {
            ++differing;
            first = i;
        }
    EXPECT_EQ(differing, 0u) << "first at value " << first << ": " << plain.pixels[first] << " against "
                             << oiio.pixels[first];
}

/// Glint's reader of a format (read_png, read_jpeg).
using NativeImageReader = std::optional<std::string> (*)(const unsigned char*, std::size_t,
                                                         const glint::codec::SizeCheck&, glint::codec::DecodedImage&);

/// `read` must take `bytes` (not leave them to OpenImageIO) and decode them as OpenImageIO
/// decodes them under the file name `name`.
inline void expect_read_as_oiio_reads(NativeImageReader read, const std::string& bytes, const std::string& name,
                                      const std::string& what) {
    SCOPED_TRACE(what);
    glint::codec::DecodedImage plain;
    const std::optional<std::string> result =
        read(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), accept_any_image_size, plain);
    ASSERT_TRUE(result.has_value()) << "left to OpenImageIO";
    EXPECT_EQ(*result, "");
    expect_same_decoded_image(plain, read_with_oiio(bytes, name));
}

/// `read` must give a refusing size check's message for a 64×32 RGB image's `bytes`, before
/// it stores any pixel.
inline void expect_refused_by_the_size_check(NativeImageReader read, const std::string& bytes) {
    glint::codec::DecodedImage decoded;
    const std::optional<std::string> result = read(
        reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
        [](int width, int height, int channels) {
            return "refused " + std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(channels);
        },
        decoded);
    ASSERT_TRUE(result.has_value());
    EXPECT_EQ(*result, "refused 64x32x3");
    EXPECT_TRUE(decoded.pixels.empty());
}

}  // namespace glint_test
