// Glint's EXR input through OpenEXR alone (src/image/exr_reader.h, in libglint_exr.so)
// against OpenImageIO's reading of the same bytes: Glint's own renders (data window, named
// channels, "glint:" attributes), every compression, half and float, tiles and MIP levels,
// channel names in any order; and the files it leaves to OpenImageIO.

#include "image/exr_reader.h"
#include "image/image_codec.h"

#include "decoded_image_expectations.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfEnvmapAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <ImfTiledOutputFile.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// A named namespace: the test binaries are unity builds.
namespace exr_reader_test {

using glint::codec::DecodedImage;

const unsigned char* bytes_of(const std::string& s) { return reinterpret_cast<const unsigned char*>(s.data()); }

/// Glint's reader on two threads (OpenEXR's pool decompresses chunks on them).
std::optional<std::string> read_exr(const unsigned char* bytes, std::size_t size, const glint::codec::SizeCheck& check,
                                    DecodedImage& out) {
    return glint::codec::exr().read_memory(bytes, size, check, 2, out);
}

void expect_read_as_oiio_reads(const std::string& bytes, const std::string& what) {
    glint_test::expect_read_as_oiio_reads(read_exr, bytes, "made.exr", what);
}

/// An EXR made with OpenEXR: values from a pattern of signs and magnitudes (so that half and
/// each lossy compression round them), one per channel, pixel and MIP level.
struct MadeExr {
    int width = 37, height = 29;
    /// Where the data window starts; the display window is `display` if set, else the data window.
    int x = 0, y = 0;
    std::optional<Imath::Box2i> display{};
    std::vector<std::pair<std::string, Imf::PixelType>> channels = {
        {"R", Imf::HALF}, {"G", Imf::HALF}, {"B", Imf::HALF}};
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    bool tiled = false;
    Imf::LevelMode levels = Imf::ONE_LEVEL;
    std::vector<std::pair<std::string, std::string>> attributes{};
    std::optional<Imf::Envmap> envmap{};
    int sampling = 1;  // of the last channel
};

float pattern(int x, int y, int c, int level) {
    return std::sin(0.37f * float(x) + 1.3f * float(y) + float(c)) * std::pow(10.0f, float((c + level) % 4 - 1));
}

Imf::Header header_of(const MadeExr& made) {
    const Imath::Box2i data(Imath::V2i(made.x, made.y), Imath::V2i(made.x + made.width - 1, made.y + made.height - 1));
    Imf::Header header(made.display.value_or(data), data);
    header.compression() = made.compression;
    for (std::size_t c = 0; c < made.channels.size(); ++c) {
        const int sampling = c + 1 == made.channels.size() ? made.sampling : 1;
        header.channels().insert(made.channels[c].first, Imf::Channel(made.channels[c].second, sampling, sampling));
    }
    for (const auto& [name, text] : made.attributes) header.insert(name, Imf::StringAttribute(text));
    if (made.envmap) header.insert("envmap", Imf::EnvmapAttribute(*made.envmap));
    if (made.tiled) header.setTileDescription(Imf::TileDescription(16, 8, made.levels));
    return header;
}

/// The pixels of `window` at MIP level `level`, channel after channel, in the channels' own
/// types (OpenEXR converts types when it reads, not when it writes).
struct Planes {
    std::vector<std::vector<float>> floats;
    std::vector<std::vector<half>> halves;
    std::vector<std::vector<unsigned>> uints;

    Planes(const MadeExr& made, const Imath::Box2i& window, int level, Imf::FrameBuffer& frame) {
        const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
        floats.resize(made.channels.size());
        halves.resize(made.channels.size());
        uints.resize(made.channels.size());
        for (std::size_t c = 0; c < made.channels.size(); ++c) {
            const int sampling = c + 1 == made.channels.size() ? made.sampling : 1;
            const Imf::PixelType type = made.channels[c].second;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const float v = pattern(x, y, int(c), level);
                    floats[c].push_back(v);
                    halves[c].push_back(half(v));
                    uints[c].push_back(unsigned(std::abs(v) * 1000.0f));
                }
            void* base = type == Imf::UINT   ? static_cast<void*>(uints[c].data())
                         : type == Imf::HALF ? static_cast<void*>(halves[c].data())
                                             : static_cast<void*>(floats[c].data());
            const std::size_t size = type == Imf::HALF ? sizeof(half) : 4;
            frame.insert(made.channels[c].first,
                         Imf::Slice::Make(type, base, window, size, size * std::size_t(w), sampling, sampling));
        }
    }
};

std::string make_exr(const MadeExr& made) {
    Imf::StdOSStream stream;
    const Imf::Header header = header_of(made);
    Imf::FrameBuffer frame;
    if (!made.tiled) {
        Imf::OutputFile file(stream, header);
        const Planes planes(made, header.dataWindow(), 0, frame);
        file.setFrameBuffer(frame);
        file.writePixels(made.height);
    } else {
        Imf::TiledOutputFile file(stream, header);
        for (int level = 0; level < file.numLevels(); ++level) {
            Imf::FrameBuffer level_frame;
            const Planes planes(made, file.dataWindowForLevel(level), level, level_frame);
            file.setFrameBuffer(level_frame);
            file.writeTiles(0, file.numXTiles(level) - 1, 0, file.numYTiles(level) - 1, level);
        }
    }
    return stream.str();
}

TEST(ExrReader, GlintsOwnRendersReadAsOpenImageIOReadsThem) {
    const std::filesystem::path dir = glint_test::temp_dir() / "exr_reader_own";
    std::filesystem::create_directories(dir);
    std::vector<float> pixels(7 * 5 * 6);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::sin(float(i)) * float(i);
    const std::vector<std::string> names = {"R", "G", "B", "A", "normal.X", "depth.Z"};
    const std::vector<std::pair<std::string, std::string>> attributes = {{"scene", "a.toml"}, {"spp", "16"}};
    glint::codec::PixelsToWrite crop{.width = 7, .height = 5, .channels = 3, .data = pixels.data(), .floats = true};
    crop.x = 2;
    crop.y = 3;
    crop.frame_width = 20;
    crop.frame_height = 10;
    crop.attributes = &attributes;
    ASSERT_EQ(glint::codec::exr().write_file((dir / "crop.exr").string(), crop), "");
    expect_read_as_oiio_reads(glint_test::read_file(dir / "crop.exr"), "a crop with attributes");

    glint::codec::PixelsToWrite aovs{
        .width = 7, .height = 5, .channels = 6, .data = pixels.data(), .floats = true, .channel_names = &names};
    ASSERT_EQ(glint::codec::exr().write_file((dir / "aovs.exr").string(), aovs), "");
    expect_read_as_oiio_reads(glint_test::read_file(dir / "aovs.exr"), "named channels");
}

TEST(ExrReader, EveryCompressionInHalfAndFloatReadsAsOpenImageIOReadsIt) {
    for (const Imf::Compression compression :
         {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION,
          Imf::PXR24_COMPRESSION, Imf::B44_COMPRESSION, Imf::B44A_COMPRESSION, Imf::DWAA_COMPRESSION,
          Imf::DWAB_COMPRESSION}) {
        const std::string what = "compression " + std::to_string(int(compression));
        expect_read_as_oiio_reads(make_exr({.compression = compression}), what + ", half");
        expect_read_as_oiio_reads(
            make_exr({.channels = {{"R", Imf::FLOAT}, {"G", Imf::FLOAT}, {"B", Imf::FLOAT}, {"A", Imf::FLOAT}},
                      .compression = compression}),
            what + ", float RGBA");
    }
    expect_read_as_oiio_reads(make_exr({.channels = {{"R", Imf::HALF}, {"G", Imf::FLOAT}, {"B", Imf::HALF}}}),
                              "half and float mixed");
    expect_read_as_oiio_reads(make_exr({.width = 1, .height = 1}), "one pixel");
}

TEST(ExrReader, TilesMipLevelsAndWindowsReadAsOpenImageIOReadsThem) {
    expect_read_as_oiio_reads(make_exr({.tiled = true}), "tiled");
    expect_read_as_oiio_reads(make_exr({.tiled = true, .levels = Imf::MIPMAP_LEVELS}), "MIP levels: the first");
    expect_read_as_oiio_reads(make_exr({.width = 40, .height = 33, .compression = Imf::PIZ_COMPRESSION, .tiled = true}),
                              "tiled, PIZ, tiles cut at the edges");
    expect_read_as_oiio_reads(
        make_exr({.x = -5, .y = 7, .display = Imath::Box2i(Imath::V2i(-10, -3), Imath::V2i(50, 60))}),
        "a data window inside a display window off the origin");
    expect_read_as_oiio_reads(make_exr({.envmap = Imf::ENVMAP_LATLONG}), "a lat-long environment");
    expect_read_as_oiio_reads(make_exr({.x = 3, .y = 4}), "a data window equal to a display window off the origin");
    expect_read_as_oiio_reads(make_exr({.display = Imath::Box2i(Imath::V2i(5, 5), Imath::V2i(20, 20))}),
                              "a data window larger than the display window");
}

TEST(ExrReader, ChannelsAreOrderedAndAlphaFoundAsOpenImageIODoes) {
    const auto named = [](std::vector<std::string> names) {
        MadeExr made{.width = 9, .height = 7, .channels = {}};
        for (std::string& name : names) made.channels.emplace_back(std::move(name), Imf::HALF);
        return make_exr(made);
    };
    expect_read_as_oiio_reads(named({"Y"}), "grey");
    expect_read_as_oiio_reads(named({"Y", "A"}), "grey and alpha");
    expect_read_as_oiio_reads(named({"A"}), "alpha alone");
    expect_read_as_oiio_reads(named({"A", "B", "G", "R"}), "RGBA");
    expect_read_as_oiio_reads(named({"r", "g", "b", "alpha"}), "lower case");
    expect_read_as_oiio_reads(named({"Red", "Green", "Blue", "Alpha"}), "names in full");
    expect_read_as_oiio_reads(named({"R", "G", "B", "Z", "ZBack", "depth", "Y", "u", "v"}), "known and unknown names");
    expect_read_as_oiio_reads(named({"real", "imag", "AR", "AG", "AB", "RA", "BA", "GA"}), "the rest of the known");
    expect_read_as_oiio_reads(named({"Y", "Z", "A", "X"}), "X, Y and Z: a vector");
    expect_read_as_oiio_reads(named({"X", "Y"}), "X and Y");
    expect_read_as_oiio_reads(named({"a.Z", "a.A", "a.Y", "a.R", "a.foo"}), "Y and Z without X");
    expect_read_as_oiio_reads(named({"diffuse.R", "diffuse.G", "diffuse.B", "R", "G", "B", "A", "normal.X", "normal.Y",
                                     "normal.Z", "a.b.A", "a.b.R"}),
                              "layers");
}

TEST(ExrReader, AttributesOtherThanGlintsAreNotKept) {
    const std::string bytes =
        make_exr({.attributes = {{"glint:spp", "4"}, {"glint:scene", "x.toml"}, {"owner", "someone"}}});
    DecodedImage decoded;
    ASSERT_EQ(read_exr(bytes_of(bytes), bytes.size(), glint_test::accept_any_image_size, decoded),
              std::optional<std::string>(""));
    const std::vector<std::pair<std::string, std::string>> expected = {{"scene", "x.toml"}, {"spp", "4"}};
    EXPECT_EQ(decoded.attributes, expected);
    expect_read_as_oiio_reads(bytes, "attributes");
}

TEST(ExrReader, LeavesOtherKindsAndBrokenFilesToOpenImageIO) {
    DecodedImage decoded;
    auto left = [&](const std::string& bytes) {
        return !read_exr(bytes_of(bytes), bytes.size(), glint_test::accept_any_image_size, decoded);
    };
    EXPECT_TRUE(left(make_exr({.channels = {{"R", Imf::UINT}, {"G", Imf::HALF}, {"B", Imf::HALF}}})));
    EXPECT_TRUE(left(make_exr({.width = 8, .height = 8, .sampling = 2})));
    // OpenImageIO frames a MIP-mapped cube map as one face.
    EXPECT_TRUE(left(
        make_exr({.width = 8, .height = 48, .tiled = true, .levels = Imf::MIPMAP_LEVELS, .envmap = Imf::ENVMAP_CUBE})));
    {
        Imf::StdOSStream stream;
        const MadeExr made{};
        Imf::Header first = header_of(made), second = header_of(made);
        first.setName("first");
        second.setName("second");
        first.setType(Imf::SCANLINEIMAGE);
        second.setType(Imf::SCANLINEIMAGE);
        const Imf::Header headers[] = {first, second};
        Imf::MultiPartOutputFile file(stream, headers, 2);
        for (int part = 0; part < 2; ++part) {
            Imf::OutputPart output(file, part);
            Imf::FrameBuffer frame;
            const Planes planes(made, first.dataWindow(), 0, frame);
            output.setFrameBuffer(frame);
            output.writePixels(made.height);
        }
        EXPECT_TRUE(left(stream.str()));
    }
    const std::string whole = make_exr({.width = 64, .height = 64, .compression = Imf::NO_COMPRESSION});
    EXPECT_TRUE(left(whole.substr(0, whole.size() / 2)));  // pixels cut short
    EXPECT_TRUE(left(whole.substr(0, 40)));                // cut inside the header
    EXPECT_TRUE(left(std::string("\x76\x2f\x31\x01", 4)));
    EXPECT_TRUE(left("not an EXR"));
    EXPECT_TRUE(decoded.pixels.empty());
    EXPECT_FALSE(left(whole));
}

TEST(ExrReader, RefusesWhatTheSizeCheckRefusesBeforeReadingPixels) {
    glint_test::expect_refused_by_the_size_check(read_exr, make_exr({.width = 64, .height = 32}));
}

}  // namespace exr_reader_test
