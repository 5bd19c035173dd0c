// The render traces camera rays eight pixels at a time as packets (Integrator::
// takes_first_hits); the images must be the ones tracing them one by one makes, bit for
// bit, for every scene in scenes/ (at 64×48), AOVs included, with and without adaptive
// sampling.

#include "glint/image/aov_film.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_format/toml_scene_loader.h"

#include "example_scenes.h"
#include "source_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {
namespace {

constexpr uint32_t kPacketsWidth = 64, kPacketsHeight = 48;

/// Another integrator's Li(), with camera rays traced one at a time (the default
/// Li_given_first_hit and takes_first_hits).
class OneRayAtATime final : public Integrator {
public:
    explicit OneRayAtATime(const Integrator& inner) : inner_(inner) {}
    Color Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const override {
        return inner_.Li(scene, ray, context);
    }

private:
    const Integrator& inner_;
};

/// Pixels of `a` that differ from `b` in any channel (bitwise, not within a tolerance).
int differing_pixels(const Image& a, const Image& b) {
    int differ = 0;
    for (std::size_t p = 0; p < std::size_t(a.width) * a.height; ++p)
        for (int c = 0; c < a.channels; ++c)
            if (a.pixels[p * a.channels + c] != b.pixels[p * b.channels + c]) {
                ++differ;
                break;
            }
    return differ;
}

/// Scene `name` rendered with camera rays in packets and one by one (with `adaptive`
/// sampling when given): how many pixels differ, in the radiance or any AOV channel.
struct PacketsAgainstSingles {
    int differing_pixels = 0;
    /// False for an integrator that takes no packets (both renders are then one by one).
    bool takes_packets = false;
};

PacketsAgainstSingles render_both_ways(const std::string& name, std::optional<AdaptiveSampling> adaptive) {
    LoadedScene loaded = load_toml_scene(glint_test::kScenesDir / (name + ".toml"));
    loaded.settings.width = kPacketsWidth;
    loaded.settings.height = kPacketsHeight;
    if (adaptive) {
        loaded.settings.samples_per_axis = 4;
        loaded.settings.adaptive = adaptive;
    }
    const RenderScene scene(std::move(loaded.scene));
    const std::unique_ptr<Integrator> integrator = make_integrator(loaded.settings);
    const OneRayAtATime one_by_one(*integrator);
    const std::vector<Aov> aovs = {Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Spp, Aov::Variance};
    Film packets(kPacketsWidth, kPacketsHeight), singles(kPacketsWidth, kPacketsHeight);
    AovFilm packet_aovs(kPacketsWidth, kPacketsHeight, aovs), single_aovs(kPacketsWidth, kPacketsHeight, aovs);
    integrator->render(scene, loaded.settings, packets, {}, nullptr, nullptr, &packet_aovs);
    one_by_one.render(scene, loaded.settings, singles, {}, nullptr, nullptr, &single_aovs);
    return {differing_pixels(packet_aovs.append_to(packets.to_image()), single_aovs.append_to(singles.to_image())),
            integrator->takes_first_hits()};
}

class CameraPackets : public testing::TestWithParam<std::string> {};

TEST_P(CameraPackets, RenderTheImageOfSingleRays) {
    const PacketsAgainstSingles result = render_both_ways(GetParam(), std::nullopt);
    EXPECT_EQ(result.differing_pixels, 0) << "of " << kPacketsWidth * kPacketsHeight
                                          << (result.takes_packets ? "" : " (this integrator takes no packets)");
}

// Adaptive sampling (2 to 16 spp) packs the pixels still sampling, wherever they are in the
// tile, and each must still take its own samples in its own order.
TEST_P(CameraPackets, RenderTheAdaptiveImageOfSingleRays) {
    const PacketsAgainstSingles result =
        render_both_ways(GetParam(), AdaptiveSampling{.min_spp = 2, .threshold = 0.02f});
    EXPECT_EQ(result.differing_pixels, 0) << "of " << kPacketsWidth * kPacketsHeight
                                          << (result.takes_packets ? "" : " (this integrator takes no packets)");
}

INSTANTIATE_TEST_SUITE_P(Scenes, CameraPackets,
                         testing::ValuesIn(glint_test::example_scene_names(glint_test::kSourceDir)),
                         [](const testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
}  // namespace glint
