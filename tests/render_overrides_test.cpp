// The render settings a caller overrides, checked by one function for the command line and
// the Python module: every value outside what a scene file accepts, and every name Glint
// does not know, is refused with the setting named as that caller spells it.

#include "glint/integrators/render_overrides.h"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace glint {
namespace {

/// The message apply_overrides gives for `set`, or a test failure if it accepts it.
std::string override_refusal(const std::function<void(RenderOverrides&)>& set, OptionSpelling spelling) {
    RenderOverrides overrides;
    set(overrides);
    RenderSettings settings;
    try {
        apply_overrides(overrides, settings, spelling);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    ADD_FAILURE() << "accepted";
    return {};
}

TEST(RenderOverrides, NamesTheSettingAsTheCallerSpellsIt) {
    const auto samples = [](RenderOverrides& o) { o.light_samples = 0; };
    EXPECT_EQ(override_refusal(samples, OptionSpelling::CommandLine).rfind("--light-samples: expected", 0), 0u);
    EXPECT_EQ(override_refusal(samples, OptionSpelling::Keyword).rfind("light_samples: expected", 0), 0u);
    EXPECT_EQ(option_name("filter-radius", OptionSpelling::Keyword), "filter_radius");
    EXPECT_EQ(option_name("filter-radius", OptionSpelling::CommandLine), "--filter-radius");
}

TEST(RenderOverrides, UnknownNamesAreRefusedWithTheChoices) {
    const OptionSpelling kw = OptionSpelling::Keyword;
    EXPECT_EQ(override_refusal([](RenderOverrides& o) { o.integrator = "photon"; }, kw),
              "integrator: expected one of whitted, path; got 'photon'");
    const std::string filter = override_refusal([](RenderOverrides& o) { o.filter = "boxy"; }, kw);
    EXPECT_EQ(filter.rfind("filter: expected one of box", 0), 0u) << filter;
    EXPECT_NE(filter.find("got 'boxy'"), std::string::npos) << filter;
    EXPECT_EQ(override_refusal([](RenderOverrides& o) { o.mis = "maximum"; }, kw),
              "mis: expected one of balance, power; got 'maximum'");
    EXPECT_EQ(override_refusal([](RenderOverrides& o) { o.aov = "albedo,glow"; }, kw).rfind("aov: expected", 0), 0u);
}

TEST(RenderOverrides, GoodValuesLandInTheSettings) {
    RenderOverrides o;
    o.width = 320;
    o.spp = 16;
    o.integrator = "path";
    o.mis = "balance";
    o.filter = "gaussian";
    RenderSettings s;
    apply_overrides(o, s, OptionSpelling::Keyword);
    EXPECT_EQ(s.width, 320u);
    EXPECT_EQ(s.samples_per_axis, 4u);
    EXPECT_EQ(s.integrator, "path");
    EXPECT_EQ(s.mis, MisHeuristic::Balance);
}

TEST(RenderOverrides, CropsArePixelsOrFractionsOfTheImage) {
    const CropRequest pixels = parse_crop("10,20,30,40");
    EXPECT_FALSE(pixels.fractions);
    EXPECT_EQ(crop_pixels(pixels, 100, 50), (PixelRect{10, 20, 30, 40}));
    // Fractions round up at both ends (pbrt's --cropwindow), so halves tile an odd side.
    const CropRequest left = parse_crop("0,0,0.5,1"), right = parse_crop("0.5,0,1.0,1");
    EXPECT_TRUE(left.fractions && right.fractions);
    EXPECT_EQ(crop_pixels(left, 101, 7), (PixelRect{0, 0, 51, 7}));
    EXPECT_EQ(crop_pixels(right, 101, 7), (PixelRect{51, 0, 101, 7}));
    EXPECT_EQ(crop_pixels(parse_crop("0,0,1,1"), 101, 7), (PixelRect{0, 0, 1, 1})) << "whole numbers are pixels";
    RenderOverrides o;
    o.width = 64;
    o.height = 48;
    o.crop = "0.25,0.5,0.75,1.0";
    RenderSettings s;
    apply_overrides(o, s);
    EXPECT_EQ(s.crop, (PixelRect{16, 24, 48, 48}));
}

TEST(RenderOverrides, BadCropsAreRefusedInWords) {
    const auto message = [](const std::string& text, uint32_t width = 640, uint32_t height = 480) {
        try {
            (void)crop_pixels(parse_crop(text), width, height);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        ADD_FAILURE() << text << " accepted";
        return std::string();
    };
    for (const char* malformed : {"", "1,2,3", "1,2,3,4,5", "a,b,c,d", "1,,3,4", "0,0,nan,1", "1 ,2,3,4"})
        EXPECT_EQ(message(malformed).rfind("--crop: expected X0,Y0,X1,Y1", 0), 0u) << malformed;
    EXPECT_EQ(message("5,5,5,10"), "--crop: expected 0 ≤ X0 < X1 and 0 ≤ Y0 < Y1; got '5,5,5,10'");
    EXPECT_EQ(message("-1,0,5,5"), "--crop: expected 0 ≤ X0 < X1 and 0 ≤ Y0 < Y1; got '-1,0,5,5'");
    EXPECT_EQ(message("0,0,1.5,1").rfind("--crop: fractions of the image go from 0 to 1", 0), 0u);
    EXPECT_EQ(message("0,0,700,10"), "--crop 0,0,700,10: the region reaches past the 640×480 image");
    EXPECT_EQ(message("0.31,0,0.35,1", 10, 10),
              "--crop 0.31,0,0.35,1 (pixels 4,0,4,10): the region covers no pixel of the 10×10 image");
}

}  // namespace
}  // namespace glint
