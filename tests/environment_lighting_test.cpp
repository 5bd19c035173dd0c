// The environment as a light in both integrators: a white furnace (a diffuse sphere under a
// uniform sky shows its albedo, whether the sky is a colour or a map), and a small bright sun
// in a map casting the shadow of a sphere on a plane. The Whitted tracer lights with the
// background only with Scene::environment_lighting.

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/integrators/path_integrator.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace glint;

namespace {

/// Mean and standard error of `n` estimates of Li along the ray from `eye` through `target`.
struct Estimate {
    double mean = 0.0;
    double stderr_ = 0.0;
};

Estimate radiance_towards(const RenderScene& scene, const Integrator& integrator, const Vec3& eye, const Vec3& target,
                          uint32_t n) {
    Sampler sampler(3, 1);
    double sum = 0.0, sum2 = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        sampler.start_pixel_sample(0, i);
        TraceContext context{sampler};
        const double v = integrator.Li(scene, Ray(eye, normalize(target - eye)), context).luminance();
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

/// A 2:1 map of radiance `sky` with, if `sun` > 0, a 2×2-pixel sun of that radiance at the
/// zenith rows (directions within 11° of +y).
std::shared_ptr<const Image> sky_map(float sky, float sun) {
    Image img(64, 32, 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) img.at(x, y, c) = (sun > 0.0f && y < 2 && x >= 31 && x < 33) ? sun : sky;
    return std::make_shared<const Image>(std::move(img));
}

/// A white-ish diffuse sphere of albedo 0.8 at the origin under `background`.
RenderScene furnace(const Background& background) {
    Scene scene;
    Material m;
    m.diffuse = Color(0.8f);
    scene.add_object(std::make_shared<Sphere>(Vec3(0.0f), 1.0f), scene.add_material(m));
    scene.background = background;
    scene.environment_lighting = true;
    return RenderScene(std::move(scene));
}

TEST(EnvironmentLighting, PathFurnaceShowsTheAlbedo) {
    // A convex diffuse sphere sees only the sky: L = albedo × 1 exactly, wherever it is seen.
    for (const Background& sky : {Background::constant(Color(1.0f)),
                                  Background::environment(BackgroundKind::Equirectangular, sky_map(1.0f, 0.0f)),
                                  Background::environment(BackgroundKind::AngularMap, std::make_shared<const Image>([] {
                                                              Image img(32, 32, 3);
                                                              std::fill(img.pixels.begin(), img.pixels.end(), 0.5f);
                                                              return img;
                                                          }()),
                                                          40.0f, 2.0f)}) {
        const RenderScene scene = furnace(sky);
        ASSERT_TRUE(scene.environment_light());
        const PathIntegrator path(8, MisHeuristic::Power);
        for (const Vec3& target : {Vec3(0.0f), Vec3(0.5f, 0.6f, 0.0f), Vec3(-0.7f, -0.5f, 0.0f)}) {
            const Estimate e = radiance_towards(scene, path, Vec3(0.3f, 0.2f, 4.0f), target, 4096);
            // Four standard errors: a correct estimator fails one such check in 16,000.
            EXPECT_NEAR(e.mean, 0.8, 4.0 * e.stderr_ + 1e-3) << "target " << target;
            EXPECT_LT(e.stderr_, 0.01) << "light sampling must make a uniform sky nearly noiseless";
        }
    }
}

/// A sphere of radius 0.5 floating at height 1 over a grey plane, under a dim sky with a
/// bright sun overhead: its shadow falls around the origin.
RenderScene sun_and_sphere() {
    Scene scene;
    Material m;
    m.diffuse = Color(0.5f);
    const uint32_t grey = scene.add_material(m);
    scene.add_object(std::make_shared<Quad>(Vec3(-4.0f, 0.0f, 4.0f), Vec3(8.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, -8.0f)),
                     grey);
    scene.add_object(std::make_shared<Sphere>(Vec3(0.0f, 1.0f, 0.0f), 0.5f), grey);
    scene.background = Background::environment(BackgroundKind::Equirectangular, sky_map(0.05f, 20000.0f));
    scene.environment_lighting = true;
    return RenderScene(std::move(scene));
}

void expect_shadow(const RenderScene& scene, const Integrator& integrator, const char* what) {
    const Vec3 eye(0.0f, 1.0f, 4.0f);  // sees the plane under the sphere past it
    const Estimate shadowed = radiance_towards(scene, integrator, eye, Vec3(0.0f, 0.0f, 0.0f), 256);
    const Estimate lit = radiance_towards(scene, integrator, eye, Vec3(1.5f, 0.0f, 0.0f), 256);
    EXPECT_GT(lit.mean, 1.0) << what;
    EXPECT_LT(shadowed.mean, 0.1 * lit.mean) << what << ": the sun's shadow is missing";
}

TEST(EnvironmentLighting, SunInTheMapCastsAShadowInThePathTracer) {
    expect_shadow(sun_and_sphere(), PathIntegrator(4, MisHeuristic::Power), "path");
}

TEST(EnvironmentLighting, SunInTheMapCastsAShadowInTheWhittedTracer) {
    expect_shadow(sun_and_sphere(), WhittedIntegrator(4, 16, 4), "whitted");
}

TEST(EnvironmentLighting, WhittedFurnaceShowsTheAlbedoOnlyWhenAsked) {
    // Direct light from a white sky onto a convex diffuse sphere: albedo × 1, and noiseless
    // for the constant sky, whose samples follow the cosine.
    const RenderScene lit = furnace(Background::constant(Color(1.0f)));
    const Estimate e = radiance_towards(lit, WhittedIntegrator(4, 4, 4), Vec3(0.3f, 0.2f, 4.0f), Vec3(0.2f), 64);
    EXPECT_NEAR(e.mean, 0.8, 1e-4);
    Scene unlit;
    Material m;
    m.diffuse = Color(0.8f);
    unlit.add_object(std::make_shared<Sphere>(Vec3(0.0f), 1.0f), unlit.add_material(m));
    unlit.background = Background::constant(Color(1.0f));
    const Estimate dark = radiance_towards(RenderScene(std::move(unlit)), WhittedIntegrator(4, 4, 4),
                                           Vec3(0.3f, 0.2f, 4.0f), Vec3(0.2f), 4);
    EXPECT_EQ(dark.mean, 0.0) << "without environment_lighting the sky is only seen";
}

}  // namespace
