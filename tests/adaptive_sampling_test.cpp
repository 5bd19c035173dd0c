// Adaptive anti-aliasing (integrators/adaptive_sampling.h): the stratified sample order, the
// error estimate, and renders of a hard edge against uniform sampling.

#include "glint/integrators/adaptive_sampling.h"
#include "glint/geometry/quad.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>

using namespace glint;

namespace {

constexpr uint32_t kAdaptiveSide = 24;

/// A quad of radiance 1 whose slanted edge crosses the view of an orthographic camera, on a
/// black background: pixels wholly on either side have no spread, pixels on the edge do.
RenderScene edge_scene() {
    Scene scene;
    Material glow;
    glow.diffuse = Color(0.0f);
    glow.emission = Color(1.0f);
    scene.emission_lights = false;
    const Vec3 corner(-0.3f, -4.0f, -1.0f);
    scene.add_object(std::make_shared<Quad>(corner, Vec3(4.0f, 0.0f, 0.0f), Vec3(-1.2f, 8.0f, 0.0f)),
                     scene.add_material(glow));
    scene.camera = Camera::orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 2.0f);
    return RenderScene(std::move(scene));
}

Film render_adaptive(const RenderScene& scene, uint32_t samples_per_axis, std::optional<AdaptiveSampling> adaptive,
                     uint32_t threads = 0) {
    RenderSettings settings;
    settings.width = settings.height = kAdaptiveSide;
    settings.samples_per_axis = samples_per_axis;
    settings.adaptive = adaptive;
    settings.threads = threads;
    Film film(kAdaptiveSide, kAdaptiveSide);
    (void)WhittedIntegrator().render(scene, settings, film);
    return film;
}

double rms_error(const Film& film, const Film& reference) {
    double sum = 0.0;
    for (uint32_t y = 0; y < kAdaptiveSide; ++y)
        for (uint32_t x = 0; x < kAdaptiveSide; ++x) sum += std::pow(film.at(x, y).r - reference.at(x, y).r, 2.0);
    return std::sqrt(sum / (kAdaptiveSide * kAdaptiveSide));
}

uint64_t total_samples(const Film& film) {
    uint64_t total = 0;
    for (uint32_t y = 0; y < kAdaptiveSide; ++y)
        for (uint32_t x = 0; x < kAdaptiveSide; ++x) total += film.samples_at(x, y);
    return total;
}

}  // namespace

TEST(AdaptiveSampling, EveryPrefixOfAPowerOfFourCoversTheCoarserGrid) {
    for (const uint32_t side : {1u, 2u, 4u, 8u, 16u}) {
        std::set<uint32_t> cells;
        for (uint32_t k = 0; k < side * side; ++k) cells.insert(progressive_cell(k, side));
        EXPECT_EQ(cells.size(), side * side) << "not a permutation for side " << side;
        for (uint32_t coarse = 1; coarse <= side; coarse *= 2) {
            // The first coarse² samples: one in each (side/coarse)² block.
            std::set<uint32_t> blocks;
            for (uint32_t k = 0; k < coarse * coarse; ++k) {
                const uint32_t cell = progressive_cell(k, side);
                const uint32_t scale = side / coarse;
                blocks.insert((cell / side / scale) * coarse + (cell % side) / scale);
            }
            EXPECT_EQ(blocks.size(), coarse * coarse) << "side " << side << ", prefix " << coarse * coarse;
        }
    }
}

TEST(AdaptiveSampling, ErrorIsTheRelativeStandardErrorOfTheMean) {
    PixelError error;
    EXPECT_TRUE(std::isinf(error.relative_error()));
    for (const float y : {1.0f, 2.0f, 3.0f, 6.0f}) error.add(y);
    // Mean 3, s² = (4 + 1 + 0 + 9)/3 = 14/3; the mean's standard error is √(14/3/4).
    EXPECT_NEAR(error.relative_error(), std::sqrt(14.0 / 12.0) / 3.01, 1e-6);
    PixelError flat;
    for (int i = 0; i < 4; ++i) flat.add(0.5f);
    EXPECT_EQ(flat.relative_error(), 0.0f);
    EXPECT_TRUE(converged({.min_spp = 4, .threshold = 0.01f}, flat, 4));
    EXPECT_FALSE(converged({.min_spp = 4, .threshold = 0.01f}, flat, 8));  // an edge's minimum
    EXPECT_FALSE(converged({.min_spp = 4, .threshold = 0.01f}, error, 4));
    // Contrast of an edge against black: four batches; of a smooth 1 % gradient: one.
    EXPECT_EQ(minimum_samples({.min_spp = 4, .threshold = 0.01f}, contrast(1.0f, 0.0f), 64), 16u);
    EXPECT_EQ(minimum_samples({.min_spp = 4, .threshold = 0.01f}, contrast(1.0f, 0.99f), 64), 4u);
}

TEST(AdaptiveSampling, SpendsSamplesOnlyNearTheEdge) {
    const RenderScene scene = edge_scene();
    const Film reference = render_adaptive(scene, 32, std::nullopt);
    const Film film = render_adaptive(scene, 8, AdaptiveSampling{.min_spp = 4, .threshold = 0.01f});
    auto on_edge = [&](uint32_t x, uint32_t y) {
        const float v = reference.at(x, y).r;
        return v > 0.0f && v < 1.0f;
    };
    int edge_pixels = 0, far_pixels = 0;
    for (uint32_t y = 0; y < kAdaptiveSide; ++y)
        for (uint32_t x = 0; x < kAdaptiveSide; ++x) {
            const uint32_t spp = film.samples_at(x, y);
            if (on_edge(x, y)) {
                ++edge_pixels;
                EXPECT_GE(spp, 16u) << "edge pixel " << x << "," << y;
                continue;
            }
            bool near = false;
            for (uint32_t ny = y > 0 ? y - 1 : 0; ny <= std::min(y + 1, kAdaptiveSide - 1); ++ny)
                for (uint32_t nx = x > 0 ? x - 1 : 0; nx <= std::min(x + 1, kAdaptiveSide - 1); ++nx)
                    near |= on_edge(nx, ny);
            if (near) continue;  // a neighbour's contrast may refine it
            ++far_pixels;
            EXPECT_EQ(spp, 4u) << "pixel " << x << "," << y << " away from the edge";
        }
    EXPECT_GT(edge_pixels, int(kAdaptiveSide / 2));
    EXPECT_GT(far_pixels, int(kAdaptiveSide * kAdaptiveSide / 2));
}

TEST(AdaptiveSampling, NoWorseThanUniformSamplingForTheSameNumberOfSamples) {
    const RenderScene scene = edge_scene();
    const Film reference = render_adaptive(scene, 32, std::nullopt);  // 1024 spp
    const Film adaptive = render_adaptive(scene, 16, AdaptiveSampling{.min_spp = 4, .threshold = 0.01f});
    const double average = double(total_samples(adaptive)) / (kAdaptiveSide * kAdaptiveSide);
    // Uniform sampling with at least as many samples in all: the next square count.
    const auto n = uint32_t(std::ceil(std::sqrt(average)));
    const Film uniform = render_adaptive(scene, n, std::nullopt);
    ASSERT_GE(total_samples(uniform), total_samples(adaptive));
    const double adaptive_error = rms_error(adaptive, reference), uniform_error = rms_error(uniform, reference);
    EXPECT_LT(adaptive_error, uniform_error) << "adaptive " << average << " spp on average, uniform " << n * n;
    std::printf("adaptive: %.2f spp on average, RMS error %.5f; uniform %u spp: %.5f\n", average, adaptive_error, n * n,
                uniform_error);
}

TEST(AdaptiveSampling, OneAndTwoThreadsRenderTheSameImage) {
    const RenderScene scene = edge_scene();
    const AdaptiveSampling adaptive{.min_spp = 2, .threshold = 0.02f};
    const Film one = render_adaptive(scene, 8, adaptive, 1), two = render_adaptive(scene, 8, adaptive, 2);
    for (uint32_t y = 0; y < kAdaptiveSide; ++y)
        for (uint32_t x = 0; x < kAdaptiveSide; ++x) {
            EXPECT_EQ(one.at(x, y), two.at(x, y));
            EXPECT_EQ(one.samples_at(x, y), two.samples_at(x, y));
        }
}

TEST(AdaptiveSampling, ExplainTakesThePixelsSamples) {
    const RenderScene scene = edge_scene();
    RenderSettings settings;
    settings.width = settings.height = kAdaptiveSide;
    settings.samples_per_axis = 8;
    settings.adaptive = AdaptiveSampling{.min_spp = 4, .threshold = 0.01f};
    Film film(kAdaptiveSide, kAdaptiveSide);
    const WhittedIntegrator integrator;
    (void)integrator.render(scene, settings, film);
    for (uint32_t x = 0; x < kAdaptiveSide; ++x) {
        const PixelExplanation e = integrator.explain(scene, settings, x, kAdaptiveSide / 2);
        EXPECT_EQ(e.samples.size(), film.samples_at(x, kAdaptiveSide / 2));
        EXPECT_EQ(e.value, film.at(x, kAdaptiveSide / 2));
    }
}

TEST(AdaptiveSampling, RefusesAMaximumThatIsNotAPowerOfFour) {
    RenderSettings settings;
    settings.width = settings.height = 4;
    settings.samples_per_axis = 3;
    settings.adaptive = AdaptiveSampling{};
    Film film(4, 4);
    EXPECT_THROW((void)WhittedIntegrator().render(edge_scene(), settings, film), std::invalid_argument);
}
