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
std::string refusal(const std::function<void(RenderOverrides&)>& set, OptionSpelling spelling) {
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
    EXPECT_EQ(refusal(samples, OptionSpelling::CommandLine).rfind("--light-samples: expected", 0), 0u);
    EXPECT_EQ(refusal(samples, OptionSpelling::Keyword).rfind("light_samples: expected", 0), 0u);
    EXPECT_EQ(option_name("filter-radius", OptionSpelling::Keyword), "filter_radius");
    EXPECT_EQ(option_name("filter-radius", OptionSpelling::CommandLine), "--filter-radius");
}

TEST(RenderOverrides, UnknownNamesAreRefusedWithTheChoices) {
    const OptionSpelling kw = OptionSpelling::Keyword;
    EXPECT_EQ(refusal([](RenderOverrides& o) { o.integrator = "photon"; }, kw),
              "integrator: expected one of whitted, path; got 'photon'");
    const std::string filter = refusal([](RenderOverrides& o) { o.filter = "boxy"; }, kw);
    EXPECT_EQ(filter.rfind("filter: expected one of box", 0), 0u) << filter;
    EXPECT_NE(filter.find("got 'boxy'"), std::string::npos) << filter;
    EXPECT_EQ(refusal([](RenderOverrides& o) { o.mis = "maximum"; }, kw),
              "mis: expected one of balance, power; got 'maximum'");
    EXPECT_EQ(refusal([](RenderOverrides& o) { o.aov = "albedo,glow"; }, kw).rfind("aov: expected", 0), 0u);
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

}  // namespace
}  // namespace glint
