// Crops of a frame and the frame they make again (glint render --crop, glint assemble):
// the pixels land where they were, and every way parts can fail to make one frame is said.

#include "glint/image/frame_assembly.h"
#include "glint/image/film.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/default_scene.h"
#include "glint/scene/render_scene.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <utility>

#include <string>
#include <vector>

namespace glint {
namespace {

/// A 7×5 frame whose every value says where it is.
Image numbered_frame() {
    Image frame(7, 5, 2);
    for (std::size_t i = 0; i < frame.pixels.size(); ++i) frame.pixels[i] = float(i);
    frame.channel_names = {"R", "Z"};
    frame.attributes = {{"scene", "a.toml"}, {"spp", "4"}};
    return frame;
}

std::string refusal(const std::vector<FramePart>& parts) {
    try {
        (void)assemble_frame(parts);
    } catch (const ImageError& e) {
        return e.what();
    }
    ADD_FAILURE() << "assembled";
    return {};
}

TEST(FrameAssembly, CropsPutTogetherAreTheFrame) {
    const Image frame = numbered_frame();
    const Image top = crop_of(frame, 0, 0, 7, 2), left = crop_of(frame, 0, 2, 3, 5), right = crop_of(frame, 3, 2, 7, 5);
    EXPECT_EQ(right.region, (FrameRegion{3, 2, 7, 5}));
    EXPECT_EQ(right.at(0, 0, 1), frame.at(3, 2, 1));
    const Image again = assemble_frame(std::vector<FramePart>{{"right", right}, {"top", top}, {"left", left}});
    EXPECT_EQ(again.pixels, frame.pixels);
    EXPECT_TRUE(again.region.whole());
    EXPECT_EQ(again.channel_names, frame.channel_names);
    EXPECT_EQ(again.attributes, frame.attributes);
    // A whole frame alone is its own assembly.
    EXPECT_EQ(assemble_frame(std::vector<FramePart>{{"all", frame}}).pixels, frame.pixels);
}

TEST(FrameAssembly, PartsThatMakeNoFrameAreRefusedNamingThem) {
    const Image frame = numbered_frame();
    const Image top = crop_of(frame, 0, 0, 7, 2), bottom = crop_of(frame, 0, 2, 7, 5);
    EXPECT_EQ(refusal({}), "nothing to assemble");
    EXPECT_EQ(refusal({{"top", top}}), "the parts leave 21 of the frame's 7×5 pixels uncovered, the first at (0, 2)");
    EXPECT_EQ(refusal({{"top", top}, {"bottom", bottom}, {"again", crop_of(frame, 2, 1, 3, 2)}}),
              "top and again overlap (both hold pixel (2, 1))");
    Image other = bottom;
    other.attributes[1].second = "16";
    EXPECT_EQ(refusal({{"top", top}, {"bottom", other}}),
              "top and bottom come from different renders (spp: 4 in top, 16 in bottom)");
    other = bottom;
    other.attributes.pop_back();
    EXPECT_EQ(refusal({{"top", top}, {"bottom", other}}),
              "top and bottom come from different renders (spp: 4 in top, nothing in bottom)");
    other = bottom;
    other.region.frame_width = 8;
    EXPECT_EQ(refusal({{"top", top}, {"bottom", other}}), "bottom is part of a 8×5 frame, top of a 7×5 one");
    other = bottom;
    other.channel_names = {"R", "G"};
    EXPECT_EQ(refusal({{"top", top}, {"bottom", other}}), "bottom has the channels R, G, top has R, Z");
    other = bottom;
    other.region.y = 3;
    EXPECT_EQ(refusal({{"top", top}, {"bottom", other}}),
              "bottom: its pixels [0, 7) × [3, 6) reach past its 7×5 frame");
    EXPECT_EQ(refusal({{"top", top}, {"frame.png", frame}}),
              "frame.png is a whole frame, not a crop of one (only an EXR written by glint render --crop keeps its "
              "place in the frame)");
}

TEST(FrameAssembly, AnExrKeepsACropsPlaceAndAttributesOtherFormatsThePixels) {
    const Image crop = crop_of(numbered_frame(), 3, 2, 7, 5);
    const std::filesystem::path folder = glint_test::temp_dir(), exr = folder / "crop.exr", pfm = folder / "crop.pfm";
    write_image(exr, crop);
    const Image read = read_image(exr, ColorEncoding::Data);
    EXPECT_EQ(read.region, crop.region);
    EXPECT_EQ(read.attributes, crop.attributes);
    EXPECT_EQ(read.pixels, crop.pixels);
    write_image(pfm, crop);
    const Image plain = read_image(pfm, ColorEncoding::Data);
    EXPECT_EQ((std::pair{plain.width, plain.height}), (std::pair{4, 3}));
    EXPECT_TRUE(plain.region.whole());
    EXPECT_TRUE(plain.attributes.empty());
}

/// The spheres scene at 64×48 (16×16 tiles: 4 × 3), rendered whole for comparison.
struct PartialRenderCase {
    RenderScene scene{make_spheres_scene()};
    RenderSettings settings = [] {
        RenderSettings s;
        s.width = 64;
        s.height = 48;
        return s;
    }();
    std::unique_ptr<Integrator> integrator = make_integrator(settings);
    Film full{64, 48};
    PartialRenderCase() { (void)integrator->render(scene, settings, full); }

    /// Pixels for which `rendered(x, y)` holds have the whole render's values; the others
    /// have no sample.
    template <class Rendered>
    void expect_only(const Film& part, Rendered&& rendered) const {
        for (uint32_t y = 0; y < 48; ++y)
            for (uint32_t x = 0; x < 64; ++x) {
                ASSERT_EQ(part.samples_at(x, y), rendered(x, y) ? 1u : 0u) << x << ", " << y;
                if (rendered(x, y)) {
                    ASSERT_EQ(part.at(x, y), full.at(x, y)) << x << ", " << y;
                }
            }
    }
};

TEST(FrameAssembly, ACroppedRenderRendersOnlyTheTilesTheCropOverlaps) {
    PartialRenderCase c;
    Film cropped(64, 48);
    c.settings.crop = PixelRect{20, 10, 40, 30};  // tiles [16, 48) × [0, 32)
    const RenderStats stats = c.integrator->render(c.scene, c.settings, cropped);
    EXPECT_EQ(stats.tiles, 4u);
    EXPECT_TRUE(stats.complete());
    c.expect_only(cropped, [](uint32_t x, uint32_t y) { return x >= 16 && x < 48 && y < 32; });
}

TEST(FrameAssembly, RenderTilesRendersTheListedTilesAsAWholeRenderDoes) {
    PartialRenderCase c;
    Film part(64, 48);
    c.settings.crop = PixelRect{0, 0, 8, 8};   // ignored: the caller chose the tiles
    const std::vector<uint32_t> tiles{1, 10};  // [16, 32) × [0, 16) and [32, 48) × [32, 48)
    EXPECT_EQ(c.integrator->render_tiles(c.scene, c.settings, part, tiles).tiles, 2u);
    c.expect_only(
        part, [](uint32_t x, uint32_t y) { return (x >= 16 && x < 32 && y < 16) || (x >= 32 && x < 48 && y >= 32); });
    const std::vector<uint32_t> past{12};
    EXPECT_THROW((void)c.integrator->render_tiles(c.scene, c.settings, part, past), std::out_of_range);
}

}  // namespace
}  // namespace glint
