// The path tracer against closed forms (furnaces), against the Whitted tracer where both
// must agree, and its determinism; plus the integrator registry.

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/path_integrator.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/scene.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace glint;

namespace {

struct ImageStats {
    double mean = 0.0;
    /// Standard error of the mean, treating pixels as independent estimates.
    double stderr_ = 0.0;
};

ImageStats red_channel_stats(const Film& film) {
    double sum = 0.0, sum2 = 0.0;
    const double count = double(film.width()) * film.height();
    for (uint32_t y = 0; y < film.height(); ++y)
        for (uint32_t x = 0; x < film.width(); ++x) {
            const double v = film.at(x, y).r;
            sum += v;
            sum2 += v * v;
        }
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count)};
}

Film render_path(const RenderScene& scene, const Integrator& integrator, uint32_t size, uint32_t samples_per_axis,
                 uint64_t seed = 0, uint32_t threads = 0) {
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samples_per_axis = samples_per_axis;
    settings.seed = seed;
    settings.threads = threads;
    Film film(size, size);
    integrator.render(scene, settings, film);
    return film;
}

/// Inside a closed sphere of albedo a and emitted radiance Le, every ray sees
/// L = Le + a·L, so L = Le/(1 − a): with a = Le = 0.5, radiance 1 (pbrt-v4's
/// integrators_test furnace).
RenderScene closed_furnace(bool emission_lights) {
    Scene scene;
    Material m;
    m.diffuse = Color(0.5f);
    m.emission = Color(0.5f);
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), scene.add_material(m));
    scene.emission_lights = emission_lights;
    scene.camera = Camera::perspective(Vec3(0.1f, 0.2f, 0.3f), Vec3(0, 0, -1), Vec3(0, 1, 0), 90.0f);
    return RenderScene(std::move(scene));
}

}  // namespace

TEST(PathFurnace, ClosedEmissiveSphereAveragesOne) {
    // 1 − 0.5^65 of the energy is within depth 64; Russian roulette keeps the estimate unbiased.
    for (const bool nee : {true, false}) {
        for (const MisHeuristic h : {MisHeuristic::Power, MisHeuristic::Balance}) {
            const RenderScene scene = closed_furnace(nee);
            const Film film = render_path(scene, PathIntegrator(64, h), 16, 4);
            const ImageStats s = red_channel_stats(film);
            EXPECT_NEAR(s.mean, 1.0, 4.0 * s.stderr_ + 1e-4)
                << (nee ? "with" : "without") << " light sampling, " << (h == MisHeuristic::Power ? "power" : "balance");
            EXPECT_LT(s.stderr_, 0.02);
        }
    }
}

TEST(PathFurnace, WhiteDiffuseSphereVanishesUnderAUniformWhiteSky) {
    Scene scene;
    Material white;
    white.diffuse = Color(1.0f);
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), scene.add_material(white));
    scene.background = Background::constant(Color(1.0f));
    scene.camera = Camera::perspective(Vec3(0, 0, 4), Vec3(0, 0, 0), Vec3(0, 1, 0), 40.0f);
    const RenderScene prepared(std::move(scene));
    const Film film = render_path(prepared, PathIntegrator(8), 12, 2);
    for (uint32_t y = 0; y < 12; ++y)
        for (uint32_t x = 0; x < 12; ++x) EXPECT_NEAR(film.at(x, y).r, 1.0f, 1e-4f) << x << "," << y;
}

namespace {

/// Mirror and glass spheres in front of a glowing panel (emission seen, not a light) over
/// a coloured sky, lit by a point light: no surface that either integrator shades with
/// direct light, so both compute the same specular chains.
Scene specular_scene() {
    Scene scene;
    Material mirror;
    mirror.diffuse = Color(0.0f);
    mirror.reflectivity = Color(0.9f, 0.8f, 0.7f);
    Material glass;
    glass.diffuse = Color(0.0f);
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    Material panel;
    panel.diffuse = Color(0.0f);
    panel.emission = Color(2.0f, 1.0f, 0.5f);
    scene.add_object(std::make_shared<Sphere>(Vec3(-0.6f, 0, 0), 0.5f), scene.add_material(mirror));
    scene.add_object(std::make_shared<Sphere>(Vec3(0.6f, 0, 0.2f), 0.5f), scene.add_material(glass));
    scene.add_object(std::make_shared<Quad>(Vec3(-2, -1, -1), Vec3(4, 0, 0), Vec3(0, 1.2f, 0)), scene.add_material(panel));
    scene.add_light(std::make_unique<PointLight>(Vec3(0, 3, 2), Color(5.0f), Falloff::None));
    scene.background = Background::constant(Color(0.2f, 0.4f, 0.8f));
    scene.emission_lights = false;
    scene.camera = Camera::perspective(Vec3(0, 0.3f, 3), Vec3(0, 0, 0), Vec3(0, 1, 0), 50.0f);
    return scene;
}

}  // namespace

TEST(PathVersusWhitted, AgreeOnAPurelySpecularScene) {
    const RenderScene scene(specular_scene());
    constexpr uint32_t kSize = 12;
    // The path tracer chooses one branch at each glass hit: average independent renders and
    // compare each pixel with a bound from their spread. Whitted renders with the same seeds,
    // so both see the same pixel positions (the sampler's pixel dimension depends only on
    // seed, pixel and sample index), and edges cannot tell them apart.
    // With 16 runs the mean over the standard error follows Student's t with 15 degrees of
    // freedom; 432 comparisons at a family-wise level of 1% need |t| < 6.5 (Bonferroni).
    constexpr int kRuns = 16;
    constexpr double kT = 6.5;
    std::vector<Film> runs, whitted_runs;
    for (int i = 0; i < kRuns; ++i) {
        runs.push_back(render_path(scene, PathIntegrator(8), kSize, 4, uint64_t(i)));
        whitted_runs.push_back(render_path(scene, WhittedIntegrator(8), kSize, 4, uint64_t(i)));
    }
    auto whitted_at = [&](uint32_t x, uint32_t y, int c) {
        double sum = 0.0;
        for (const Film& f : whitted_runs) sum += f.at(x, y)[c];
        return sum / kRuns;
    };
    int checked = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0, sum2 = 0.0;
                for (const Film& f : runs) {
                    const double v = f.at(x, y)[c];
                    sum += v;
                    sum2 += v * v;
                }
                const double mean = sum / kRuns;
                const double stderr_ = std::sqrt(std::max(0.0, sum2 / kRuns - mean * mean) / (kRuns - 1));
                EXPECT_NEAR(mean, whitted_at(x, y, c), kT * stderr_ + 1e-4) << x << "," << y << " channel " << c;
                ++checked;
            }
    EXPECT_EQ(checked, int(kSize * kSize * 3));
}

TEST(PathVersusWhitted, BothAreIdenticalForAnyThreadCountWithAreaLights) {
    Scene scene = specular_scene();
    Material white;
    white.diffuse = Color(0.7f);
    scene.add_object(std::make_shared<Quad>(Vec3(-3, -0.5f, 3), Vec3(6, 0, 0), Vec3(0, 0, -6)), scene.add_material(white));
    scene.add_area_light(std::make_shared<Sphere>(Vec3(1, 2, 1), 0.4f), Emitter{Color(4.0f), false});
    scene.emission_lights = true;
    const RenderScene prepared(std::move(scene));
    for (const char* name : {"whitted", "path"}) {
        RenderSettings settings;
        settings.integrator = name;
        settings.light_samples = 4;
        const auto integrator = make_integrator(settings);
        const Film one = render_path(prepared, *integrator, 20, 2, 5, 1);
        const Film two = render_path(prepared, *integrator, 20, 2, 5, 2);
        const Film other_seed = render_path(prepared, *integrator, 20, 2, 6, 2);
        bool identical = true, differs = false;
        for (uint32_t y = 0; y < 20; ++y)
            for (uint32_t x = 0; x < 20; ++x) {
                identical = identical && one.at(x, y) == two.at(x, y);
                differs = differs || !(one.at(x, y) == other_seed.at(x, y));
            }
        EXPECT_TRUE(identical) << name;
        EXPECT_TRUE(differs) << name << ": another seed must give another image";
    }
}

TEST(IntegratorRegistry, MakesEachByNameAndRejectsUnknownNames) {
    RenderSettings settings;
    for (const std::string_view name : integrator_names()) {
        settings.integrator = std::string(name);
        EXPECT_NE(make_integrator(settings), nullptr) << name;
    }
    settings.integrator = "pathtracer";
    try {
        (void)make_integrator(settings);
        FAIL() << "an unknown integrator must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("whitted, path"), std::string::npos) << e.what();
    }
}

TEST(PathIntegrator, WarnsThatItIgnoresTheAmbientTerm) {
    EXPECT_TRUE(PathIntegrator().warnings(RenderScene(Scene())).empty());
    Scene ambient;
    ambient.ambient_light = Color(0.1f);
    const RenderScene scene(std::move(ambient));
    ASSERT_EQ(PathIntegrator().warnings(scene).size(), 1u);
    EXPECT_TRUE(WhittedIntegrator().warnings(scene).empty());
}
