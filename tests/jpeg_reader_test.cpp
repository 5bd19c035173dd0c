// Glint's own JPEG reader (src/image/jpeg_reader.h) against OpenImageIO's reading of the same
// bytes: grey and colour, every chroma subsampling libjpeg writes, progressive and arithmetic
// coding, restart markers, odd sizes; and the files it leaves to OpenImageIO.

#include "image/jpeg_reader.h"
#include "image/image_codec.h"

#include "decoded_image_expectations.h"
#include "source_paths.h"
#include "test_files.h"

#include <gtest/gtest.h>

// jpeglib.h needs FILE and size_t declared before it (libjpeg.txt).
#include <cstdio>

#include <jpeglib.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

// A named namespace: the test binaries are unity builds, and png_reader_test.cpp has helpers
// of the same names in its anonymous one.
namespace jpeg_reader_test {

namespace fs = std::filesystem;
using glint::codec::DecodedImage;

const unsigned char* bytes_of(const std::string& s) { return reinterpret_cast<const unsigned char*>(s.data()); }

void expect_read_as_oiio_reads(const std::string& bytes, const std::string& what) {
    glint_test::expect_read_as_oiio_reads(glint::codec::read_jpeg, bytes, "made.jpg", what);
}

/// A JPEG made with libjpeg from a pattern of gradients and noise (so that every block has
/// detail for the DCT to round): `components` 1 (grey), 3 (RGB, stored as YCbCr) or 4 (CMYK).
struct MadeJpeg {
    int width = 37, height = 29, components = 3;
    /// The luma component's sampling factors; chroma stays 1×1 (1, 1 is 4:4:4, 2, 2 is 4:2:0).
    int luma_h = 2, luma_v = 2;
    int quality = 90;
    bool progressive = false, arithmetic = false;
    unsigned restart_rows = 0;
    std::string comment{};
};

std::string make_jpeg(const MadeJpeg& made) {
    jpeg_compress_struct info{};
    jpeg_error_mgr error{};
    info.err = jpeg_std_error(&error);
    jpeg_create_compress(&info);
    unsigned char* out = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &out, &size);
    info.image_width = JDIMENSION(made.width);
    info.image_height = JDIMENSION(made.height);
    info.input_components = made.components;
    info.in_color_space = made.components == 1 ? JCS_GRAYSCALE : made.components == 3 ? JCS_RGB : JCS_CMYK;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, made.quality, TRUE);
    if (made.components == 3) {
        info.comp_info[0].h_samp_factor = made.luma_h;
        info.comp_info[0].v_samp_factor = made.luma_v;
    }
    if (made.progressive) jpeg_simple_progression(&info);
    info.arith_code = made.arithmetic ? TRUE : FALSE;
    info.restart_in_rows = int(made.restart_rows);
    jpeg_start_compress(&info, TRUE);
    if (!made.comment.empty())
        jpeg_write_marker(&info, JPEG_COM, bytes_of(made.comment), unsigned(made.comment.size()));
    std::vector<unsigned char> row(std::size_t(made.width) * std::size_t(made.components));
    uint32_t noise = 12345;
    for (int y = 0; y < made.height; ++y) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            noise = noise * 1664525u + 1013904223u;
            const auto x = int(i) / made.components, c = int(i) % made.components;
            row[i] = static_cast<unsigned char>((x * 7 + y * 5 + c * 60) % 256 / 2 + (noise >> 25));
        }
        JSAMPROW rows[1] = {row.data()};
        jpeg_write_scanlines(&info, rows, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::string bytes(reinterpret_cast<const char*>(out), size);
    std::free(out);
    return bytes;
}

TEST(JpegReader, GreyAndEveryChromaSubsamplingReadAsOpenImageIOReadsThem) {
    expect_read_as_oiio_reads(make_jpeg({.components = 1}), "grey");
    for (const auto& [h, v] : {std::pair{1, 1}, std::pair{2, 1}, std::pair{1, 2}, std::pair{2, 2}})
        expect_read_as_oiio_reads(make_jpeg({.luma_h = h, .luma_v = v}),
                                  "colour, luma sampled " + std::to_string(h) + "×" + std::to_string(v));
    expect_read_as_oiio_reads(make_jpeg({.width = 1, .height = 1}), "one pixel");
    expect_read_as_oiio_reads(make_jpeg({.width = 256, .height = 3, .quality = 100}), "quality 100");
    expect_read_as_oiio_reads(make_jpeg({.width = 64, .height = 64, .quality = 10}), "quality 10");
}

TEST(JpegReader, ProgressiveArithmeticRestartsAndCommentsReadAsOpenImageIOReadsThem) {
    expect_read_as_oiio_reads(make_jpeg({.progressive = true}), "progressive colour");
    expect_read_as_oiio_reads(make_jpeg({.components = 1, .progressive = true}), "progressive grey");
    expect_read_as_oiio_reads(make_jpeg({.arithmetic = true}), "arithmetic coding");
    expect_read_as_oiio_reads(make_jpeg({.width = 80, .height = 70, .restart_rows = 1}), "restart markers");
    expect_read_as_oiio_reads(make_jpeg({.comment = "made by a test"}), "a comment");
}

TEST(JpegReader, ASharedPhotographicTextureReadsAsOpenImageIOReadsIt) {
    const fs::path file = glint_test::kSharedDataDir / "textures" / "checker_2048.jpg";
    if (!fs::exists(file)) GTEST_SKIP() << "needs " << file.string() << " (../shared/data, not in a user's clone)";
    expect_read_as_oiio_reads(glint_test::read_file(file), file.string());
}

TEST(JpegReader, LeavesCmykAndBrokenFilesToOpenImageIO) {
    DecodedImage decoded;
    auto left = [&](const std::string& bytes) {
        return !glint::codec::read_jpeg(bytes_of(bytes), bytes.size(), glint_test::accept_any_image_size, decoded);
    };
    EXPECT_TRUE(left(make_jpeg({.components = 4})));
    const std::string whole = make_jpeg({.width = 64, .height = 64});
    EXPECT_TRUE(left(whole.substr(0, whole.size() / 2)));  // libjpeg warns, and pads with grey
    EXPECT_TRUE(left(whole.substr(0, 100)));               // cut inside the header: an error
    EXPECT_TRUE(left("\xFF\xD8\xFF"));
    EXPECT_TRUE(left("not a JPEG"));
    EXPECT_FALSE(left(whole));
}

TEST(JpegReader, RefusesWhatTheSizeCheckRefusesBeforeReadingPixels) {
    glint_test::expect_refused_by_the_size_check(glint::codec::read_jpeg, make_jpeg({.width = 64, .height = 32}));
}

}  // namespace jpeg_reader_test
