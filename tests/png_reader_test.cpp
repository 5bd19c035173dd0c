// Glint's own PNG reader (src/image/png_reader.h) against OpenImageIO's reading of the same
// bytes: every colour type and bit depth, palettes and tRNS transparency, interlacing, the
// gamma and sRGB chunks, every 8- and 16-bit value; and the files it leaves to OpenImageIO.

#include "image/png_reader.h"
#include "image/image_codec.h"

#include "decoded_image_expectations.h"
#include "source_paths.h"
#include "test_files.h"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using glint::codec::DecodedImage;

void expect_read_as_oiio_reads(const std::string& bytes, const std::string& what) {
    glint_test::expect_read_as_oiio_reads(glint::codec::read_png, bytes, "made.png", what);
}

/// A PNG made with libpng: `samples` are the rows as PNG stores them (big-endian 16-bit,
/// packed low bit depths), written with the chunks a test asks for.
struct MadePng {
    int width = 16, height = 16, bit_depth = 8, color_type = PNG_COLOR_TYPE_GRAY;
    bool interlaced = false;
    std::vector<png_color> palette{};
    std::vector<png_byte> palette_alpha{};      ///< tRNS for a palette
    std::optional<png_color_16> transparent{};  ///< tRNS for grey or RGB
    std::optional<double> gamma{};
    bool srgb = false;
    std::optional<std::pair<int, int>> offset{};
    std::vector<std::pair<std::string, std::string>> texts{};
};

int channels_of(int color_type) {
    switch (color_type) {
        case PNG_COLOR_TYPE_GRAY:
        case PNG_COLOR_TYPE_PALETTE:
            return 1;
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            return 2;
        case PNG_COLOR_TYPE_RGB:
            return 3;
        default:
            return 4;
    }
}

void append_bytes(png_structp png, png_bytep data, png_size_t n) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
void flush_nothing(png_structp) {}

/// The PNG for `made`; its samples take every value of the bit depth (every index of the
/// palette) in turn, once the image holds enough of them.
std::string make_png(const MadePng& made) {
    constexpr unsigned seed = 0;
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &out, append_bytes, flush_nothing);
    png_set_IHDR(png, info, png_uint_32(made.width), png_uint_32(made.height), made.bit_depth, made.color_type,
                 made.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!made.palette.empty()) png_set_PLTE(png, info, made.palette.data(), int(made.palette.size()));
    if (!made.palette_alpha.empty())
        png_set_tRNS(png, info, made.palette_alpha.data(), int(made.palette_alpha.size()), nullptr);
    if (made.transparent) png_set_tRNS(png, info, nullptr, 0, &*made.transparent);
    if (made.gamma) png_set_gAMA(png, info, *made.gamma);
    if (made.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (made.offset) png_set_oFFs(png, info, made.offset->first, made.offset->second, PNG_OFFSET_PIXEL);
    std::vector<png_text> texts;
    for (const auto& [key, text] : made.texts)
        texts.push_back({PNG_TEXT_COMPRESSION_NONE, const_cast<char*>(key.c_str()), const_cast<char*>(text.c_str()),
                         text.size(), 0, nullptr, nullptr});
    if (!texts.empty()) png_set_text(png, info, texts.data(), int(texts.size()));
    png_write_info(png, info);
    const std::size_t row_bytes =
        (std::size_t(made.width) * std::size_t(channels_of(made.color_type)) * std::size_t(made.bit_depth) + 7) / 8;
    const unsigned levels =
        made.color_type == PNG_COLOR_TYPE_PALETTE ? unsigned(made.palette.size()) : 1u << std::min(made.bit_depth, 8);
    std::vector<png_byte> samples(row_bytes * std::size_t(made.height));
    if (made.bit_depth == 16) {
        // 40503 is odd, so 65536 samples take every 16-bit value once.
        for (std::size_t j = 0; j < samples.size() / 2; ++j) {
            const auto value = unsigned(j * 40503u + seed) & 0xffffu;
            samples[2 * j] = png_byte(value >> 8);
            samples[2 * j + 1] = png_byte(value & 0xff);
        }
    } else if (made.bit_depth == 8) {
        for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = png_byte((i + seed) % 256);
    } else {
        // Packed samples, each taking every value of the depth (or index of the palette) in turn.
        const int per_byte = 8 / made.bit_depth;
        for (std::size_t i = 0; i < samples.size() * std::size_t(per_byte); ++i) {
            const unsigned value = unsigned(i + seed) % levels;
            samples[i / per_byte] |= png_byte(value << (8 - made.bit_depth * (1 + int(i % per_byte))));
        }
    }
    std::vector<png_bytep> rows(std::size_t(made.height));
    for (int y = 0; y < made.height; ++y) rows[std::size_t(y)] = samples.data() + std::size_t(y) * row_bytes;
    png_write_image(png, rows.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return out;
}

std::vector<png_color> palette_of(int n) {
    std::vector<png_color> palette;
    for (int i = 0; i < n; ++i) palette.push_back({png_byte(i * 7), png_byte(255 - i), png_byte(i * 13 % 256)});
    return palette;
}

TEST(PngReader, TheExampleTexturesReadAsOpenImageIOReadsThem) {
    for (const fs::path& file : {glint_test::kScenesDir / "assets" / "kenney_prototype_orange_checker_1024.png",
                                 glint_test::kTestDataDir / "left_opaque_right_clear.png"})
        expect_read_as_oiio_reads(glint_test::read_file(file), file.string());
}

TEST(PngReader, EveryColourTypeAndBitDepthReadsAsOpenImageIOReadsIt) {
    for (const int depth : {1, 2, 4, 8, 16})
        expect_read_as_oiio_reads(make_png({.bit_depth = depth}), "grey, " + std::to_string(depth) + " bits");
    expect_read_as_oiio_reads(make_png({.width = 256, .height = 256, .bit_depth = 16}), "grey, every 16-bit value");
    for (const int depth : {8, 16}) {
        const std::string bits = std::to_string(depth) + " bits";
        expect_read_as_oiio_reads(make_png({.bit_depth = depth, .color_type = PNG_COLOR_TYPE_GRAY_ALPHA}),
                                  "grey and alpha, " + bits);
        expect_read_as_oiio_reads(make_png({.bit_depth = depth, .color_type = PNG_COLOR_TYPE_RGB}), "RGB, " + bits);
        expect_read_as_oiio_reads(make_png({.bit_depth = depth, .color_type = PNG_COLOR_TYPE_RGB_ALPHA}),
                                  "RGBA, " + bits);
    }
    for (const int depth : {1, 2, 4, 8})
        expect_read_as_oiio_reads(
            make_png({.bit_depth = depth, .color_type = PNG_COLOR_TYPE_PALETTE, .palette = palette_of(1 << depth)}),
            "palette, " + std::to_string(depth) + " bits");
}

TEST(PngReader, TransparencyInterlacingAndGammaReadAsOpenImageIOReadsThem) {
    expect_read_as_oiio_reads(make_png({.bit_depth = 4,
                                        .color_type = PNG_COLOR_TYPE_PALETTE,
                                        .palette = palette_of(16),
                                        .palette_alpha = {0, 128, 255, 7}}),
                              "palette with tRNS");
    expect_read_as_oiio_reads(make_png({.bit_depth = 2, .transparent = png_color_16{0, 0, 0, 0, 2}}),
                              "2-bit grey with tRNS");
    expect_read_as_oiio_reads(make_png({.bit_depth = 16, .transparent = png_color_16{0, 0, 0, 0, 515}}),
                              "16-bit grey with tRNS");
    expect_read_as_oiio_reads(make_png({.color_type = PNG_COLOR_TYPE_RGB, .transparent = png_color_16{0, 3, 4, 5, 0}}),
                              "RGB with tRNS");
    expect_read_as_oiio_reads(
        make_png({.width = 13, .height = 11, .color_type = PNG_COLOR_TYPE_RGB_ALPHA, .interlaced = true}),
        "interlaced RGBA");
    expect_read_as_oiio_reads(make_png({.width = 9, .height = 7, .bit_depth = 1, .interlaced = true}),
                              "interlaced 1-bit grey");
    for (const double gamma : {1.0, 0.996, 1.006, 0.45455, 2.2})
        expect_read_as_oiio_reads(make_png({.color_type = PNG_COLOR_TYPE_RGB, .gamma = gamma}),
                                  "gAMA " + std::to_string(gamma));
    expect_read_as_oiio_reads(make_png({.color_type = PNG_COLOR_TYPE_RGB, .srgb = true}), "sRGB");
    expect_read_as_oiio_reads(make_png({.color_type = PNG_COLOR_TYPE_RGB, .gamma = 0.45455, .srgb = true}),
                              "sRGB and gAMA");
    expect_read_as_oiio_reads(make_png({.texts = {{"Software", "a test"}, {"Title", "made"}}}), "text chunks");
}

TEST(PngReader, LeavesOffsetsGlintTextAndBrokenFilesToOpenImageIO) {
    DecodedImage decoded;
    auto left = [&](const std::string& bytes) {
        return !glint::codec::read_png(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                                       glint_test::accept_any_image_size, decoded);
    };
    EXPECT_TRUE(left(make_png({.offset = std::pair{3, 4}})));
    EXPECT_TRUE(left(make_png({.texts = {{"glint:spp", "4"}}})));
    const std::string whole = make_png({});
    EXPECT_TRUE(left(whole.substr(0, whole.size() - 20)));
    std::string damaged = whole;
    damaged[40] ^= 0x55;  // inside IDAT: its CRC no longer matches
    EXPECT_TRUE(left(damaged));
    EXPECT_FALSE(left(whole));
}

TEST(PngReader, RefusesWhatTheSizeCheckRefusesBeforeReadingPixels) {
    glint_test::expect_refused_by_the_size_check(
        glint::codec::read_png, make_png({.width = 64, .height = 32, .color_type = PNG_COLOR_TYPE_RGB}));
}

}  // namespace
