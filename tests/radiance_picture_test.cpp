// Radiance pictures read by Glint itself (src/image/radiance_picture.h): the same floats as
// OpenImageIO gives, bit for bit, on every .hdr the examples and shared/data hold and on
// pictures made here in each storage (flat, run-length coded with runs and literals, coded
// scanlines then flat ones); what each broken picture is told; and pictures in another
// orientation left to OpenImageIO.
#include "image/radiance_picture.h"
#include "image/image_codec.h"

#include "glint/image/image_io.h"
#include "source_paths.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace glint::codec {
namespace {

namespace fs = std::filesystem;

std::string accept_any(int, int, int) { return ""; }

const unsigned char* data_of(const std::string& bytes) { return reinterpret_cast<const unsigned char*>(bytes.data()); }

/// What Glint reads, or the error text it gives.
std::string native_error(const std::string& bytes, Image& out) {
    const std::optional<std::string> error = read_radiance_picture(data_of(bytes), bytes.size(), accept_any, out);
    return error ? *error : "left to OpenImageIO";
}

void expect_same_as_openimageio(const std::string& bytes, const std::string& name) {
    Image ours;
    DecodedImage theirs;
    ASSERT_EQ(native_error(bytes, ours), "") << name;
    ASSERT_EQ(oiio().read_memory(data_of(bytes), bytes.size(), "picture.hdr", accept_any, theirs), "") << name;
    ASSERT_EQ(ours.width, theirs.width) << name;
    ASSERT_EQ(ours.height, theirs.height) << name;
    ASSERT_EQ(ours.channels, theirs.channels) << name;
    EXPECT_EQ(ours.channel_names, theirs.channel_names) << name;
    EXPECT_FALSE(theirs.integer_data) << name;
    ASSERT_EQ(ours.pixels.size(), theirs.pixels.size()) << name;
    // Bit for bit: memcmp also tells -0 from 0 and compares NaNs.
    EXPECT_EQ(std::memcmp(ours.pixels.data(), theirs.pixels.data(), ours.pixels.size() * sizeof(float)), 0) << name;
    for (std::size_t i = 0, shown = 0; i < ours.pixels.size() && shown < 5; ++i)
        if (std::memcmp(&ours.pixels[i], &theirs.pixels[i], 4) != 0) {
            ++shown;
            ADD_FAILURE() << i << ": " << ours.pixels[i] << " vs " << theirs.pixels[i];
        }
}

/// The four bytes of pixel i of a made-up picture: every mantissa byte occurs, exponents
/// from 2^-36 to 2^24 (and 0, black), with stretches of repeats so that coded channels hold
/// runs as well as literals, and stretches of 150 without (literals of the longest, 128).
void test_pixel(int i, unsigned char rgbe[4]) {
    const int stretch = (i / 5) % 3 == 0 && (i / 150) % 2 == 0 ? i / 5 : i;
    rgbe[0] = uint8_t(stretch * 37);
    rgbe[1] = uint8_t(stretch * 11 + 3);
    rgbe[2] = uint8_t(255 - stretch);
    rgbe[3] = uint8_t(i % 7 == 0 ? 0 : 100 + (stretch * 13) % 61);
}

std::string header(int width, int height) {
    return "#?RADIANCE\n# made by radiance_picture_test\nEXPOSURE=2\nFORMAT=32-bit_rle_rgbe\n\n-Y " +
           std::to_string(height) + " +X " + std::to_string(width) + "\n";
}

std::string flat_picture(int width, int height) {
    std::string bytes = header(width, height);
    for (int i = 0; i < width * height; ++i) {
        unsigned char rgbe[4];
        test_pixel(i, rgbe);
        bytes.append(reinterpret_cast<const char*>(rgbe), 4);
    }
    return bytes;
}

/// One channel of a scanline, coded: runs of four or more repeats, literals between.
void code_channel(const std::vector<unsigned char>& values, std::string& bytes) {
    std::size_t i = 0;
    while (i < values.size()) {
        std::size_t run = 1;
        while (i + run < values.size() && run < 127 && values[i + run] == values[i]) ++run;
        if (run >= 4) {
            bytes += char(128 + run);
            bytes += char(values[i]);
            i += run;
            continue;
        }
        std::size_t literal = 0;
        while (i + literal < values.size() && literal < 128) {
            std::size_t ahead = 1;
            while (i + literal + ahead < values.size() && ahead < 4 &&
                   values[i + literal + ahead] == values[i + literal])
                ++ahead;
            if (ahead >= 4) break;
            ++literal;
        }
        bytes += char(literal);
        bytes.append(reinterpret_cast<const char*>(&values[i]), literal);
        i += literal;
    }
}

/// Run-length coded scanlines, the ones `coded` says (the others flat).
template <typename Coded>
std::string coded_picture(int width, int height, Coded coded) {
    std::string bytes = header(width, height);
    for (int y = 0; y < height; ++y) {
        std::vector<unsigned char> channels[4];
        for (int x = 0; x < width; ++x) {
            unsigned char rgbe[4];
            test_pixel(y * width + x, rgbe);
            if (!coded(y)) bytes.append(reinterpret_cast<const char*>(rgbe), 4);
            for (int c = 0; c < 4; ++c) channels[c].push_back(rgbe[c]);
        }
        if (!coded(y)) continue;
        bytes += {char(2), char(2), char(width >> 8), char(width & 0xff)};
        for (const auto& channel : channels) code_channel(channel, bytes);
    }
    return bytes;
}

std::string coded_picture(int width, int height) {
    return coded_picture(width, height, [](int) { return true; });
}

TEST(RadiancePicture, MadePicturesReadAsOpenImageIOReadsThem) {
    expect_same_as_openimageio(flat_picture(5, 3), "flat 5×3 (too narrow to code)");
    expect_same_as_openimageio(flat_picture(40, 6), "flat 40×6");
    expect_same_as_openimageio(coded_picture(300, 7), "coded 300×7");
    expect_same_as_openimageio(coded_picture(8, 2), "coded 8×2");
    expect_same_as_openimageio(coded_picture(64, 9, [](int y) { return y % 3 != 1; }),
                               "coded and flat scanlines mixed");
}

TEST(RadiancePicture, EveryMantissaAndExponentIsTheByteTimesTwoToTheExponentMinus136) {
    // One scanline per exponent byte, every mantissa 1-255 in it (flat: 255 pixels and no
    // 2, 2 mark). The value is exact in float: eight significant bits, at worst 2^-135.
    std::string bytes = header(255, 256);
    for (int e = 0; e < 256; ++e)
        for (int m = 1; m < 256; ++m) bytes += {char(m), char(m / 2), char(255 - m), char(e)};
    Image ours;
    DecodedImage theirs;
    ASSERT_EQ(native_error(bytes, ours), "");
    ASSERT_EQ(oiio().read_memory(data_of(bytes), bytes.size(), "picture.hdr", accept_any, theirs), "");
    for (int e = 0; e < 256; ++e)
        for (int m = 1; m < 256; ++m) {
            const std::size_t at = (std::size_t(e) * 255 + std::size_t(m - 1)) * 3;
            const int mantissas[3] = {m, m / 2, 255 - m};
            for (int c = 0; c < 3; ++c) {
                const double exact = e == 0 ? 0.0 : std::ldexp(double(mantissas[c]), e - 136);
                ASSERT_EQ(double(ours.pixels[at + c]), exact) << "mantissa " << mantissas[c] << ", exponent " << e;
                // OpenImageIO 2.4.7 is one ulp below the exact value at exponent bytes 40, 223
                // and 226 (2^-96, 2^87, 2^90: never in a real sky) and exact elsewhere.
                ASSERT_LE(std::abs(ours.pixels[at + c] - theirs.pixels[at + c]),
                          std::nextafter(ours.pixels[at + c], INFINITY) - ours.pixels[at + c])
                    << "mantissa " << mantissas[c] << ", exponent " << e;
            }
        }
}

TEST(RadiancePicture, EveryHdrOfTheExamplesAndSharedDataReadsAsOpenImageIOReadsIt) {
    std::vector<fs::path> files;
    for (const fs::path& dir : {glint_test::kScenesDir / "assets", glint_test::kSharedDataDir / "env"})
        if (fs::is_directory(dir))
            for (const auto& entry : fs::recursive_directory_iterator(dir))
                if (entry.path().extension() == ".hdr") files.push_back(entry.path());
    ASSERT_GE(files.size(), 2u) << "scenes/assets holds two .hdr files";
    for (const fs::path& file : files) expect_same_as_openimageio(glint_test::read_file(file), file.string());
}

TEST(RadiancePicture, ReadImageGivesTheLinearValues) {
    const fs::path file = glint_test::temp_dir() / "made.hdr";
    const std::string bytes = coded_picture(16, 4);
    glint_test::write_file(file, bytes);
    const Image image = read_image(file, ColorEncoding::Color);
    ASSERT_EQ(image.width, 16);
    ASSERT_EQ(image.height, 4);
    ASSERT_EQ(image.channels, 3);
    // Pixel 9 (x 9, row 0): bytes (37·9, 11·9 + 3, 255 − 9, 100 + 13·9 mod 61) =
    // (77, 102, 246, 156), each mantissa × 2^(156 − 136).
    unsigned char rgbe[4];
    test_pixel(9, rgbe);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(image.at(9, 0, c), std::ldexp(float(rgbe[c]), int(rgbe[3]) - 136)) << c;
    EXPECT_EQ(image.at(7, 0, 0), 0.0f) << "exponent byte 0 is black";
}

TEST(RadiancePicture, BrokenPicturesSayWhatIsWrong) {
    const std::string good = coded_picture(64, 4);
    const std::size_t pixels_at = header(64, 4).size();
    struct Case {
        std::string bytes, expected;
    };
    std::string wrong_width = good;
    wrong_width[pixels_at + 3] = char(63);
    std::string zero_count = good;
    zero_count[pixels_at + 4] = char(0);
    std::string overlong_run = good;
    overlong_run[pixels_at + 4] = char(128 + 127);
    const Case cases[] = {
        {"#?RADIANCE", "not a Radiance picture"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n-Y 2 +X 2\n", "the header ends without the empty line"},
        {"#?RADIANCE\n\n", "the header ends without the resolution line"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\nabcd",
         "stored as 32-bit_rle_xyze; expected FORMAT=32-bit_rle_rgbe"},
        {"#?RADIANCE\n\n-Y 0 +X 4\n", "the resolution line is '-Y 0 +X 4'"},
        {"#?RADIANCE\n\n-Y 2 +X 4 junk\n", "the resolution line is '-Y 2 +X 4 junk'"},
        {"#?RADIANCE\n\nsize 4 4\n", "the resolution line is 'size 4 4'"},
        {"#?RADIANCE\n\n-Y 2 +X 2\n12345678", "the pixels end early: 8 bytes cannot hold 2×2 pixels"},
        // Too narrow to be coded: the bytes must hold every pixel flat, 4 bytes each.
        {flat_picture(5, 3).substr(0, header(5, 3).size() + 4 * 14),
         "the pixels end early: 56 bytes cannot hold 5×3 pixels"},
        {good.substr(0, good.size() - 3), "the pixels end early: scanline 4 is cut off"},
        {wrong_width, "scanline 1 says it is 63 pixels wide; expected 64"},
        {zero_count, "scanline 1 has a run of 0 bytes"},
        {overlong_run, "scanline 1 has a run of 127 bytes where 64 are left"},
    };
    for (const Case& c : cases) {
        Image out;
        EXPECT_NE(native_error(c.bytes, out).find(c.expected), std::string::npos)
            << "got '" << native_error(c.bytes, out) << "' for a picture that should give '" << c.expected << "'";
    }
}

TEST(RadiancePicture, SizeIsCheckedBeforePixelsAreAllocated) {
    Image out;
    const std::string bytes = "#?RADIANCE\n\n-Y 100000 +X 100000\n";
    const auto refuse = [](int width, int height, int channels) {
        return std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(channels) + " refused";
    };
    EXPECT_EQ(read_radiance_picture(data_of(bytes), bytes.size(), refuse, out), "100000x100000x3 refused");
    EXPECT_TRUE(out.pixels.empty());
}

TEST(RadiancePicture, OtherOrientationsAreLeftToOpenImageIO) {
    const std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 1 +X 2\n\x80\x80\x80\x81\x40\x40\x40\x81";
    Image out;
    EXPECT_EQ(native_error(bytes, out), "left to OpenImageIO");
    const fs::path file = glint_test::temp_dir() / "upside_down.hdr";
    glint_test::write_file(file, bytes);
    const Image image = read_image(file, ColorEncoding::Color);
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 1);
}

}  // namespace
}  // namespace glint::codec
