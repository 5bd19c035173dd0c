// PNG output (src/image/png_writer.cpp): the file is read back here byte by byte, not by
// the library that might forgive it. Every chunk's CRC holds, the IDAT chunks join into one
// zlib stream that inflates completely with a matching Adler-32, the rows unfilter to the
// display levels written (srgb_byte of each value), and the bytes are the same on one
// thread or several. Sizes make one stripe, many stripes, a stripe of a single row and a
// single pixel.
#include "glint/image/image_io.h"
#include "glint/image/srgb_byte.h"
#include "test_files.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

using namespace glint;
namespace fs = std::filesystem;

namespace {

uint32_t big_endian_at(const std::string& bytes, std::size_t at) {
    uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes.at(at + i));
    return v;
}

/// The PNG specification's filters (ISO/IEC 15948 §9.2), undone: whatever filter a row
/// names, so the test does not assume the writer's choice.
std::vector<uint8_t> unfilter(const std::vector<uint8_t>& filtered, int width, int height, int channels) {
    const std::size_t row = std::size_t(width) * channels, bpp = std::size_t(channels);
    std::vector<uint8_t> out(row * height);
    for (int y = 0; y < height; ++y) {
        const uint8_t* in = &filtered[std::size_t(y) * (row + 1)];
        uint8_t* cur = &out[std::size_t(y) * row];
        const uint8_t* prev = y > 0 ? cur - row : nullptr;
        for (std::size_t i = 0; i < row; ++i) {
            const int a = i >= bpp ? cur[i - bpp] : 0, b = prev ? prev[i] : 0, c = prev && i >= bpp ? prev[i - bpp] : 0;
            int predicted = 0;
            switch (in[0]) {
                case 0:
                    break;
                case 1:
                    predicted = a;
                    break;
                case 2:
                    predicted = b;
                    break;
                case 3:
                    predicted = (a + b) / 2;
                    break;
                case 4: {
                    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
                    predicted = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
                    break;
                }
                default:
                    ADD_FAILURE() << "row " << y << " names filter " << int(in[0]);
                    return out;
            }
            cur[i] = static_cast<uint8_t>(in[1 + i] + predicted);
        }
    }
    return out;
}

/// Checks the file's structure and returns its samples, row by row from the top.
std::vector<uint8_t> decode(const std::string& png, int width, int height, int channels) {
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    std::string stream, types;
    for (std::size_t at = 8; at < png.size();) {
        const uint32_t length = big_endian_at(png, at);
        const std::string type = png.substr(at + 4, 4), data = png.substr(at + 8, length);
        const auto* typed = reinterpret_cast<const Bytef*>(png.data() + at + 4);
        EXPECT_EQ(big_endian_at(png, at + 8 + length), uint32_t(crc32(0, typed, length + 4))) << type << " CRC";
        if (type == "IHDR") {
            EXPECT_EQ(big_endian_at(data, 0), uint32_t(width));
            EXPECT_EQ(big_endian_at(data, 4), uint32_t(height));
            EXPECT_EQ(int(data.at(8)), 8);  // bits per sample
            EXPECT_EQ(int(data.at(9)), channels == 1 ? 0 : channels == 2 ? 4 : 2);
        }
        if (type == "IDAT") stream += data;
        if (types.empty() || types.substr(types.size() - 4) != type) types += type;
        at += 12 + length;
    }
    EXPECT_EQ(types.substr(0, 4), "IHDR");
    EXPECT_NE(types.find("sRGB"), std::string::npos);
    EXPECT_EQ(types.substr(types.size() - 8), "IDATIEND") << "one run of IDAT chunks, then IEND";
    // uncompress() fails unless the stream ends with a final block and its Adler-32 matches.
    const std::size_t filtered_size = std::size_t(height) * (std::size_t(width) * channels + 1);
    std::vector<uint8_t> filtered(filtered_size + 1);
    uLongf size = uLongf(filtered.size());
    EXPECT_EQ(uncompress(filtered.data(), &size, reinterpret_cast<const Bytef*>(stream.data()), uLong(stream.size())),
              Z_OK);
    EXPECT_EQ(size, filtered_size);
    filtered.resize(filtered_size);
    return unfilter(filtered, width, height, channels);
}

/// A render-like image: smooth gradients with noise, so filters and matches both matter.
Image test_image(int width, int height, int channels) {
    Image image(width, height, channels);
    std::mt19937 rng(uint32_t(width * 31 + height * 7 + channels));
    std::uniform_real_distribution<float> noise(0.0f, 0.05f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                image.at(x, y, c) = float(x + 2 * y + 37 * c) / float(width + 2 * height + 100) + noise(rng);
    return image;
}

}  // namespace

// Not in the anonymous namespace: the test classes TEST_F derives from it are external.
class PngOutputTest : public ::testing::Test {
protected:
    void SetUp() override { dir_ = glint_test::temp_dir(); }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(PngOutputTest, RowsComeBackAsTheLevelsWritten) {
    // 700×300 RGB: rows of 2,101 filtered bytes, five stripes. 1×70000 grey: 3 stripes of
    // thin rows. 50000×2 grey + alpha: rows longer than a stripe. 1×1: one byte.
    struct Size {
        int width, height, channels;
    };
    for (const Size s : {Size{700, 300, 3}, Size{1, 70000, 1}, Size{50000, 2, 2}, Size{1, 1, 3}, Size{5, 3, 1}}) {
        const Image image = test_image(s.width, s.height, s.channels);
        const fs::path path = dir_ / "out.png";
        write_image(path, image);
        const std::vector<uint8_t> samples = decode(glint_test::read_file(path), s.width, s.height, s.channels);
        ASSERT_EQ(samples.size(), image.pixels.size());
        for (std::size_t i = 0; i < samples.size(); ++i)
            ASSERT_EQ(int(samples[i]), int(srgb_byte(image.pixels[i])))
                << s.width << "×" << s.height << "×" << s.channels << ", sample " << i;
    }
}

TEST_F(PngOutputTest, SameBytesOnOneThreadOrSeveral) {
    const Image image = test_image(640, 480, 3);
    std::string bytes[2];
    const int threads[2] = {1, 2};
    for (int i = 0; i < 2; ++i) {
        const fs::path path = dir_ / ("threads" + std::to_string(threads[i]) + ".png");
        tbb::task_arena(threads[i]).execute([&] { write_image(path, image); });
        bytes[i] = glint_test::read_file(path);
    }
    EXPECT_EQ(bytes[0], bytes[1]);
}

TEST_F(PngOutputTest, ManyStripesReadBackThroughOpenImageIO) {
    const Image image = test_image(700, 300, 3);
    const fs::path path = dir_ / "stripes.png";
    write_image(path, image);
    const Image back = read_image(path, ColorEncoding::Data);
    ASSERT_EQ(back.width, 700);
    ASSERT_EQ(back.height, 300);
    ASSERT_EQ(back.channels, 3);
    for (std::size_t i = 0; i < back.pixels.size(); ++i)
        ASSERT_EQ(std::lround(back.pixels[i] * 255.0f), long(srgb_byte(image.pixels[i]))) << "sample " << i;
}
