// Streaming a render to a display server (tev's protocol): the packets as documented, the
// image a viewer rebuilds from them equal to the file written, and a render that never
// fails or waits for an absent or restarting viewer.

#include "cli_runner.h"
#include "tev_receiver.h"

#include "glint/image/image_io.h"
#include "glint/io/display_connection.h"
#include "glint/io/film_stream.h"
#include "glint/io/tev_protocol.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace fs = std::filesystem;

namespace {

const std::array<std::string, 3> kRgb = {"R", "G", "B"};

/// Every value of `image` received, and equal to `expected` (interleaved RGB).
void expect_same_pixels(const glint_test::ReceivedImage& image, const glint::Image& expected) {
    ASSERT_EQ(image.width, expected.width);
    ASSERT_EQ(image.height, expected.height);
    ASSERT_EQ(image.channels, std::vector<std::string>(kRgb.begin(), kRgb.end()));
    std::size_t differing = 0;
    for (int y = 0; y < expected.height; ++y)
        for (int x = 0; x < expected.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float got = image.values[(std::size_t(y) * expected.width + x) * 3 + c];
                const float want = expected.pixels[(std::size_t(y) * expected.width + x) * expected.channels + c];
                // Bit for bit: both are the film's pixel values as floats.
                differing += std::memcmp(&got, &want, sizeof(float)) != 0;
            }
    EXPECT_EQ(differing, 0u) << "of " << expected.width * expected.height * 3 << " values";
}

bool has_whole_image(const glint_test::ViewerState& state, const std::string& name) {
    const auto it = state.images.find(name);
    if (it == state.images.end()) return false;
    for (float v : it->second.values)
        if (std::isnan(v)) return false;
    return true;
}

}  // namespace

TEST(TevProtocol, CreateImageIsTheDocumentedPacket) {
    // tev-protocol.md's worked example: CreateImage("glint", 640×480, R,G,B), grab focus.
    const std::vector<uint8_t> expected = {0x1E, 0,    0, 0, 0x04, 0x01, 'g', 'l', 'i', 'n', 't', 0, 0x80, 0x02, 0, 0,
                                           0xE0, 0x01, 0, 0, 0x03, 0,    0,   0,   'R', 0,   'G', 0, 'B',  0};
    EXPECT_EQ(glint::tev::create_image("glint", 640, 480, kRgb, true), expected);
}

TEST(TevProtocol, UpdateImagePlacesInterleavedValues) {
    glint_test::ViewerState viewer;
    const auto create = glint::tev::create_image("img", 4, 3, kRgb, false);
    glint_test::apply_tev_packet(create.data() + 4, create.size() - 4, viewer);
    // A 2×1 rectangle at (1, 2): pixel (1,2) = (1,2,3), pixel (2,2) = (4,5,6).
    const std::vector<float> values = {1, 2, 3, 4, 5, 6};
    const auto update = glint::tev::update_image("img", kRgb, 1, 2, 2, 1, values);
    uint32_t length;
    std::memcpy(&length, update.data(), 4);
    EXPECT_EQ(length, update.size()) << "the length counts the whole packet";
    EXPECT_EQ(update[4], 6) << "UpdateImageV3";
    glint_test::apply_tev_packet(update.data() + 4, update.size() - 4, viewer);
    const glint_test::ReceivedImage& image = viewer.images.at("img");
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(image.values[(2 * 4 + 1) * 3 + c], values[c]);
        EXPECT_EQ(image.values[(2 * 4 + 2) * 3 + c], values[3 + c]);
        EXPECT_TRUE(std::isnan(image.values[(2 * 4 + 3) * 3 + c])) << "outside the rectangle";
    }
    EXPECT_THROW((void)glint::tev::update_image("img", kRgb, 0, 0, 2, 2, values), std::invalid_argument);
    EXPECT_THROW((void)glint::tev::create_image(std::string("a\0b", 3), 1, 1, kRgb, false), std::invalid_argument);
}

TEST(DisplayAddress, ParsesHostAndPort) {
    const glint::DisplayAddress a = glint::parse_display_address("127.0.0.1:14158");
    EXPECT_EQ(a.host, "127.0.0.1");
    EXPECT_EQ(a.port, 14158);
    const glint::DisplayAddress b = glint::parse_display_address("[::1]:1");
    EXPECT_EQ(b.host, "::1");
    EXPECT_EQ(b.port, 1);
    EXPECT_EQ(b.text(), "[::1]:1");
    EXPECT_EQ(glint::parse_display_address("localhost:65535").text(), "localhost:65535");
}

TEST(DisplayAddress, RefusesWhatIsNotHostAndPort) {
    for (const char* bad : {"", "localhost", "localhost:", ":14158", "host:0", "host:65536", "host:14158x", "host:-1",
                            "::1:14158", "[]:14158"}) {
        try {
            (void)glint::parse_display_address(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("expected HOST:PORT"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(std::string("got '") + bad + "'"), std::string::npos) << e.what();
        }
    }
}

TEST(DisplayServer, ViewerShowsExactlyTheImageWritten) {
    const glint_test::TevReceiver viewer;
    const fs::path dir = glint_test::temp_dir();
    const fs::path output = dir / "spheres.exr";
    const glint_test::CliResult r =
        glint_test::run_cli(GLINT_CLI,
                            "render --width 100 --height 70 --spp 4 -o " + output.string() +
                                " --display-server 127.0.0.1:" + std::to_string(viewer.port()),
                            dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    ASSERT_TRUE(viewer.wait_for([&](const auto& s) { return has_whole_image(s, output.string()); }));
    const glint_test::ViewerState state = viewer.state();
    EXPECT_EQ(state.error, "");
    EXPECT_EQ(state.connections, 1);
    const glint_test::ReceivedImage& image = state.images.at(output.string());
    // 100×70 in 16×16 tiles: 7×5 updates, each sent once.
    EXPECT_EQ(image.updates, 35u);
    expect_same_pixels(image, glint::read_image(output));
}

TEST(DisplayServer, RenderWithoutViewerWarnsOnceAndWritesItsImage) {
    int port;
    {
        // A port that was free a moment ago, with nobody listening now.
        const glint_test::TevReceiver closed;
        port = closed.port();
    }
    const fs::path dir = glint_test::temp_dir();
    const fs::path output = dir / "out.png";
    const glint_test::CliResult r = glint_test::run_cli(
        GLINT_CLI,
        "render --width 40 --height 30 -o " + output.string() + " --display-server 127.0.0.1:" + std::to_string(port),
        dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(output));
    EXPECT_EQ(r.err, "warning: display server 127.0.0.1:" + std::to_string(port) +
                         ": cannot connect (Connection refused); the render goes on without it and keeps trying\n");
}

TEST(DisplayServer, MalformedAddressIsAnErrorBeforeRendering) {
    const fs::path dir = glint_test::temp_dir();
    const fs::path output = dir / "out.png";
    const glint_test::CliResult r =
        glint_test::run_cli(GLINT_CLI, "render -o " + output.string() + " --display-server localhost", dir);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "glint: error: --display-server: expected HOST:PORT, such as 127.0.0.1:14158 or [::1]:14158 (no port); "
              "got 'localhost'\n");
    EXPECT_FALSE(fs::exists(output));
}

TEST(FilmStream, ReconnectsToARestartedViewerAndSendsEverythingAgain) {
    const glint_test::TevReceiver viewer(/*drop_after_create=*/true);
    glint::Film film(40, 20);
    glint::TileGrid tiles(40, 20);
    for (uint32_t y = 0; y < 20; ++y)
        for (uint32_t x = 0; x < 40; ++x) film.add_sample(x, y, glint::Color(float(x), float(y), 0.5f), 1.0f);
    std::vector<std::string> warnings;
    glint::FilmStream stream({"127.0.0.1", viewer.port()}, "film", film, tiles,
                             [&](const std::string& w) { warnings.push_back(w); });
    const uint32_t half = tiles.count() / 2;
    for (uint32_t t = 0; t < half; ++t) tiles.mark_done(t);
    // The viewer takes the CreateImage of the first connection and quits (a reset), losing
    // the tiles sent after it...
    ASSERT_TRUE(viewer.wait_for([](const auto& s) { return s.connections == 1 && s.images.count("film"); }));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    // ...so the stream's next send fails, it connects again and sends every finished tile.
    for (uint32_t t = half; t < tiles.count(); ++t) tiles.mark_done(t);
    ASSERT_TRUE(viewer.wait_for([](const auto& s) { return s.connections == 2 && has_whole_image(s, "film"); },
                                std::chrono::seconds(5)));
    stream.finish();
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(viewer.state().error, "");
    expect_same_pixels(viewer.state().images.at("film"), film.to_image());
}
