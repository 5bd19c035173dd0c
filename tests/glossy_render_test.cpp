// Rough surfaces through both integrators: roughness 0 renders exactly as before the key
// existed, glossy renders are deterministic, and the Whitted tracer (glossy samples, light
// samples, MIS between them) agrees with the path tracer where both must.

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/path_integrator.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

using namespace glint;

namespace {

Film render_glossy(const RenderScene& scene, const RenderSettings& settings) {
    Film film(settings.width, settings.height);
    make_integrator(settings)->render(scene, settings, film);
    return film;
}

bool identical(const Film& a, const Film& b) {
    for (uint32_t y = 0; y < a.height(); ++y)
        for (uint32_t x = 0; x < a.width(); ++x)
            if (!(a.at(x, y) == b.at(x, y))) return false;
    return true;
}

/// Gold-coloured rough metal and frosted glass in front of an emissive panel that is an area
/// light, under a point light and a coloured sky: every surface is glossy or black, so the
/// Whitted tracer's glossy samples and the path tracer's BSDF samples estimate the same
/// light. Dielectrics block shadow rays, as they do in the path tracer.
Scene glossy_scene() {
    Scene scene;
    Material gold;
    gold.diffuse = Color(0.0f);
    gold.reflectivity = Color(1.0f, 0.78f, 0.34f);
    gold.fresnel_mirror = true;
    gold.roughness = 0.3f;
    Material frosted;
    frosted.diffuse = Color(0.0f);
    frosted.transparency = 1.0f;
    frosted.ior = 1.5f;
    frosted.roughness = 0.25f;
    Material panel;
    panel.diffuse = Color(0.0f);
    panel.emission = Color(3.0f, 1.5f, 0.75f);
    scene.add_object(std::make_shared<Sphere>(Vec3(-0.6f, 0, 0), 0.5f), scene.add_material(gold));
    scene.add_object(std::make_shared<Sphere>(Vec3(0.6f, 0, 0.2f), 0.5f), scene.add_material(frosted));
    scene.add_object(std::make_shared<Quad>(Vec3(-2, -1, -1), Vec3(4, 0, 0), Vec3(0, 1.2f, 0)),
                     scene.add_material(panel));
    scene.add_light(std::make_unique<PointLight>(Vec3(0, 3, 2), Color(5.0f), Falloff::None));
    scene.background = Background::constant(Color(0.2f, 0.4f, 0.8f));
    scene.dielectric_shadows = DielectricShadows::Opaque;
    scene.camera = Camera::perspective(Vec3(0, 0.3f, 3), Vec3(0, 0, 0), Vec3(0, 1, 0), 50.0f);
    return scene;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(GlossyRender, RoughnessZeroIsBitIdenticalToNoRoughness) {
    // whitted1980 has a mirror, a glass and a diffuse floor; the same file with `roughness =
    // 0` in every material must give the same bits with both integrators, and a roughness
    // just above 0 must not (so that the comparison can fail).
    const std::string text = read_text(glint_test::kScenesDir / "whitted1980.toml");
    auto with_roughness = [&](const std::string& value) {
        std::string t = text;
        int materials = 0;
        for (std::size_t at = t.find("[[materials]]\n"); at != std::string::npos;
             at = t.find("[[materials]]\n", at + 1)) {
            t.insert(at + 14, "roughness = " + value + "\n");
            ++materials;
        }
        EXPECT_EQ(materials, 3);
        return t;
    };
    for (const char* integrator : {"whitted", "path"}) {
        auto film_of = [&](const std::string& scene_text) {
            LoadedScene loaded = load_toml_scene_string(scene_text, "whitted1980.toml", glint_test::kScenesDir);
            loaded.settings.width = 48;
            loaded.settings.height = 36;
            loaded.settings.integrator = integrator;
            const RenderScene prepared(std::move(loaded.scene));
            return render_glossy(prepared, loaded.settings);
        };
        const Film plain = film_of(text);
        EXPECT_TRUE(identical(plain, film_of(with_roughness("0")))) << integrator;
        EXPECT_FALSE(identical(plain, film_of(with_roughness("0.05")))) << integrator;
    }
}

TEST(GlossyRender, IdenticalForAnyThreadCount) {
    const RenderScene prepared(glossy_scene());
    for (const char* name : {"whitted", "path"}) {
        RenderSettings settings;
        settings.integrator = name;
        settings.width = 24;
        settings.height = 20;
        settings.samples_per_axis = 2;
        settings.seed = 9;
        settings.glossy_samples = 3;
        settings.threads = 1;
        const Film one = render_glossy(prepared, settings);
        settings.threads = 2;
        const Film two = render_glossy(prepared, settings);
        EXPECT_TRUE(identical(one, two)) << name;
        settings.seed = 10;
        EXPECT_FALSE(identical(one, render_glossy(prepared, settings)))
            << name << ": another seed must give another image";
    }
}

TEST(GlossyRender, WhittedAgreesWithThePathTracerOnAGlossyScene) {
    // Both integrators are random here: compare the means of 48 independent renders of each
    // with the standard error of their difference, over regions large enough for the means
    // to be close to normal (single pixels at a silhouette have heavy tails: 7 standard
    // errors at 48 runs, none at 256). The whole image, its left half (the gold sphere) and
    // its right half (the frosted glass), per channel: |t| < 4.5 rejects correct tracers with
    // probability 6·10⁻⁵ in all. A Whitted tracer that counted the panel's emission in full
    // through glossy samples as well as through its MIS-weighted light samples is 1.9% too
    // bright in the image, 6.6 standard errors.
    const RenderScene scene(glossy_scene());
    constexpr uint32_t kSize = 12;
    constexpr int kRuns = 48;
    RenderSettings settings;
    settings.width = settings.height = kSize;
    settings.samples_per_axis = 16;
    settings.max_depth = 8;
    settings.light_samples = 2;
    settings.glossy_samples = 4;
    const PathIntegrator path_tracer(settings.max_depth);
    const WhittedIntegrator whitted_tracer(settings.max_depth, settings.light_samples, settings.glossy_samples);
    std::vector<Film> path, whitted;
    for (int i = 0; i < kRuns; ++i) {
        settings.seed = uint64_t(i);
        path.emplace_back(kSize, kSize);
        path_tracer.render(scene, settings, path.back());
        whitted.emplace_back(kSize, kSize);
        whitted_tracer.render(scene, settings, whitted.back());
    }
    const struct {
        const char* name;
        uint32_t x0, x1;
    } regions[] = {{"image", 0, kSize}, {"left half", 0, kSize / 2}, {"right half", kSize / 2, kSize}};
    for (const auto& region : regions)
        for (int c = 0; c < 3; ++c) {
            // Mean of the region over the runs, and the squared standard error of that mean.
            auto statistics = [&](const std::vector<Film>& runs) {
                double sum = 0.0, sum2 = 0.0;
                for (const Film& film : runs) {
                    double v = 0.0;
                    for (uint32_t y = 0; y < kSize; ++y)
                        for (uint32_t x = region.x0; x < region.x1; ++x) v += film.at(x, y)[c];
                    v /= double(kSize * (region.x1 - region.x0));
                    sum += v;
                    sum2 += v * v;
                }
                const double mean = sum / kRuns;
                return std::pair{mean, std::max(0.0, sum2 / kRuns - mean * mean) / (kRuns - 1)};
            };
            const auto [p, p_se2] = statistics(path);
            const auto [w, w_se2] = statistics(whitted);
            EXPECT_NEAR(w, p, 4.5 * std::sqrt(p_se2 + w_se2)) << region.name << ", channel " << c;
            EXPECT_GT(p, 0.3) << region.name << " must be lit";
        }
}
