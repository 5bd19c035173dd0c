#include "glint/image/film.h"
#include "glint/image/image_io.h"
#include "glint/math/color.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <tbb/task_arena.h>

using namespace glint;
namespace fs = std::filesystem;

// Not in an anonymous namespace: the test classes TEST_F derives from it are external.
class ImageIoTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("glint_image_io_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static Image gradient() {
        Image img(8, 4, 3);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) {
                img.at(x, y, 0) = float(x) / 7.0f;
                img.at(x, y, 1) = float(y) / 3.0f;
                img.at(x, y, 2) = 2.5f;  // above 1: survives only in float formats
            }
        return img;
    }

    fs::path dir_;
};

TEST_F(ImageIoTest, FloatFormatsRoundTripLinearValues) {
    const Image img = gradient();
    for (const char* ext : {".exr", ".pfm", ".hdr"}) {
        const fs::path p = dir_ / (std::string("out") + ext);
        write_image(p, img);
        const Image back = read_image(p);
        ASSERT_EQ(back.width, 8) << ext;
        ASSERT_EQ(back.height, 4) << ext;
        // Radiance HDR stores 8-bit mantissas with a shared exponent: ~1% accuracy.
        const float eps = std::string(ext) == ".hdr" ? 0.02f : 1e-6f;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x)
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.at(x, y, c), img.at(x, y, c), eps) << ext;
    }
}

TEST_F(ImageIoTest, PngIsSrgbEncodedAndDecodedBack) {
    Image img(2, 1, 3);
    for (int c = 0; c < 3; ++c) {
        img.at(0, 0, c) = 0.21404f;  // linear value whose sRGB encoding is 0.5
        img.at(1, 0, c) = 4.0f;      // clipped to white
    }
    const fs::path p = dir_ / "out.png";
    write_image(p, img);
    const Image raw = read_image(p, ColorEncoding::Data);
    EXPECT_NEAR(raw.at(0, 0, 0), 0.5f, 1.0f / 255.0f);
    EXPECT_NEAR(raw.at(1, 0, 0), 1.0f, 1e-6f);
    const Image decoded = read_image(p);
    EXPECT_NEAR(decoded.at(0, 0, 1), 0.21404f, 0.005f);
}

TEST_F(ImageIoTest, PngKeepsChannelCountsAndRowOrderAndRoundsToTheNearestLevel) {
    // Grey, grey + alpha and RGB; each value a distinct display level, rows from the top.
    for (const int channels : {1, 2, 3}) {
        Image img(3, 2, channels);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                for (int c = 0; c < channels; ++c)
                    img.at(x, y, c) = srgb_to_linear(float(40 * (y * 3 + x) + 7 * c + 3) / 255.0f);
        const fs::path p = dir_ / ("grey" + std::to_string(channels) + ".png");
        write_image(p, img);
        const Image back = read_image(p, ColorEncoding::Data);
        ASSERT_EQ(back.channels, channels);
        ASSERT_EQ(back.width, 3);
        ASSERT_EQ(back.height, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                for (int c = 0; c < channels; ++c)
                    EXPECT_FLOAT_EQ(back.at(x, y, c) * 255.0f, float(40 * (y * 3 + x) + 7 * c + 3))
                        << channels << " channel(s), pixel " << x << "," << y << " channel " << c;
    }
}

TEST_F(ImageIoTest, ExposureScalesDisplayOutput) {
    Image img(1, 1, 3);
    for (int c = 0; c < 3; ++c) img.at(0, 0, c) = 0.25f;
    WriteOptions plus_one_stop;
    plus_one_stop.exposure = 1.0f;
    write_image(dir_ / "bright.png", img, plus_one_stop);
    EXPECT_NEAR(read_image(dir_ / "bright.png").at(0, 0, 0), 0.5f, 0.005f);
}

TEST_F(ImageIoTest, FailedWriteLeavesNoFile) {
    const fs::path missing_dir = dir_ / "no" / "such" / "dir" / "out.png";
    EXPECT_THROW(write_image(missing_dir, gradient()), ImageError);
    EXPECT_FALSE(fs::exists(missing_dir));
    EXPECT_THROW(write_image(dir_ / "out.xyz", gradient()), ImageError);
    EXPECT_TRUE(fs::is_empty(dir_)) << "no temporary or partial file may remain";
}

TEST_F(ImageIoTest, ReadErrorsNameTheFile) {
    try {
        (void)read_image(dir_ / "absent.png");
        FAIL() << "expected ImageError";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("absent.png"), std::string::npos);
    }
    const fs::path garbage = dir_ / "garbage.png";
    std::ofstream(garbage) << "this is not a png";
    EXPECT_THROW((void)read_image(garbage), ImageError);
}

TEST_F(ImageIoTest, AnExrIsTheSameBytesWhateverTheThreadsAndTheTime) {
    // Rows enough for several of ZIP's 16-row chunks, compressed on however many threads.
    Image img(64, 100, 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = float(i % 977) / 97.0f;
    img.attributes = {{"scene", "a.toml"}};
    const auto bytes_written_on = [&](int threads, const char* name) {
        tbb::task_arena arena(threads);
        arena.execute([&] { write_image(dir_ / name, img); });
        std::ifstream in(dir_ / name, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const std::string one = bytes_written_on(1, "one.exr"), two = bytes_written_on(2, "two.exr");
    EXPECT_EQ(one, bytes_written_on(1, "again.exr")) << "two writes of one image differ (a time stamp?)";
    EXPECT_EQ(one, two) << "one and two threads write different files";
    const Image back = read_image(dir_ / "two.exr");
    EXPECT_EQ(back.pixels, img.pixels);
    EXPECT_EQ(back.attributes, img.attributes);
}

TEST_F(ImageIoTest, AnExrOfOneChannelKeepsOneChannel) {
    Image img(4, 2, 1);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = 0.5f * float(i);
    write_image(dir_ / "grey.exr", img);
    const Image back = read_image(dir_ / "grey.exr");
    ASSERT_EQ(back.channels, 1);
    EXPECT_EQ(back.pixels, img.pixels);
}

TEST(Film, ToImageKeepsLinearValuesRowMajorFromTheTop) {
    Film film(3, 2);
    film.add_sample(2, 1, Color(1, 2, 3), 1.0f);
    const Image img = film.to_image();
    EXPECT_EQ(img.channels, 3);
    EXPECT_FLOAT_EQ(img.at(2, 1, 0), 1.0f);
    EXPECT_FLOAT_EQ(img.at(2, 1, 2), 3.0f);
    EXPECT_FLOAT_EQ(img.at(0, 0, 0), 0.0f);
}
