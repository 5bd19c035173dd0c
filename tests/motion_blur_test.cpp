// Motion blur in rendered images: a moving sphere's coverage of each pixel against the
// closed form, a static scene unchanged by its shutter, and determinism.

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/integrators/path_integrator.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/lights/light.h"
#include "glint/scene/default_scene.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace glint;

namespace {

// An orthographic camera sees x in [-4, 4], y in [-1, 1] on kBlurWidth × kBlurHeight pixels of
// 0.25 × 0.25; a sphere of radius kRadius of radiance 1 moves along x from kFrom to kTo
// while the shutter is open, over a black background.
constexpr uint32_t kBlurWidth = 32, kBlurHeight = 8;
constexpr double kRadius = 0.5, kFrom = -2.0, kTo = 2.0, kPixel = 0.25;

Scene moving_sphere_scene(const Shutter& shutter) {
    Scene scene;
    Material glow;
    glow.diffuse = Color(0.0f);
    glow.emission = Color(1.0f);
    scene.emission_lights = false;  // seen, not sampled: a moving object may not light the scene
    const uint32_t object =
        scene.add_object(std::make_shared<Sphere>(Vec3(0.0f), float(kRadius)), scene.add_material(glow));
    scene.set_motion(object, AnimatedTransform({{0.0f, Transform::translate({float(kFrom), 0, 0})},
                                                {1.0f, Transform::translate({float(kTo), 0, 0})}}));
    scene.camera = Camera::orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 2.0f);
    scene.camera.set_shutter(shutter);
    return scene;
}

/// The fraction of the time in [open, close] that the moving sphere covers the point (x, y)
/// of the image plane: its centre kFrom + (kTo − kFrom)·t lies within the half chord
/// √(r² − y²) of x for t in an interval.
double covered_fraction(double x, double y, const Shutter& shutter) {
    if (std::abs(y) >= kRadius) return 0.0;
    const double h = std::sqrt(kRadius * kRadius - y * y);
    const double t0 = std::max(double(shutter.open), (x - h - kFrom) / (kTo - kFrom));
    const double t1 = std::min(double(shutter.close), (x + h - kFrom) / (kTo - kFrom));
    return std::max(0.0, t1 - t0) / (double(shutter.close) - double(shutter.open));
}

/// The expected value of pixel (px, py): the covered fraction averaged over the pixel's
/// area (a box filter of radius ½ spreads samples uniformly over it), by the midpoint rule.
double expected_pixel(uint32_t px, uint32_t py, const Shutter& shutter) {
    constexpr int kSteps = 200;
    double sum = 0.0;
    for (int j = 0; j < kSteps; ++j)
        for (int i = 0; i < kSteps; ++i) {
            const double x = -4.0 + (px + (i + 0.5) / kSteps) * kPixel;
            const double y = 1.0 - (py + (j + 0.5) / kSteps) * kPixel;
            sum += covered_fraction(x, y, shutter);
        }
    return sum / (kSteps * kSteps);
}

Film render_blurred(Scene scene, const Integrator& integrator, uint32_t samples_per_axis, uint32_t threads = 0) {
    RenderSettings settings;
    settings.width = scene.camera.projection() == Projection::Orthographic ? kBlurWidth : 48;
    settings.height = scene.camera.projection() == Projection::Orthographic ? kBlurHeight : 36;
    settings.samples_per_axis = samples_per_axis;
    settings.threads = threads;
    const RenderScene prepared(std::move(scene));
    Film film(settings.width, settings.height);
    (void)integrator.render(prepared, settings, film);
    return film;
}

bool same_pixels(const Film& a, const Film& b) {
    for (uint32_t y = 0; y < a.height(); ++y)
        for (uint32_t x = 0; x < a.width(); ++x)
            if (!(a.at(x, y) == b.at(x, y))) return false;
    return true;
}

void expect_coverage(const Integrator& integrator, const Shutter& shutter) {
    // 32² samples a pixel; each sample sees radiance 1 or 0, so a pixel's mean has standard
    // deviation at most √(p(1 − p)/1024) ≤ 0.016, and 5σ bounds it (stratification only
    // shrinks it).
    constexpr uint32_t kAxis = 32;
    const Film film = render_blurred(moving_sphere_scene(shutter), integrator, kAxis);
    int lit = 0;
    for (uint32_t y = 0; y < kBlurHeight; ++y)
        for (uint32_t x = 0; x < kBlurWidth; ++x) {
            const double p = expected_pixel(x, y, shutter);
            const double sigma = std::sqrt(p * (1.0 - p) / double(kAxis * kAxis));
            EXPECT_NEAR(film.at(x, y).r, p, 5.0 * sigma + 2e-3) << "pixel " << x << "," << y;
            lit += p > 0.0;
        }
    EXPECT_GT(lit, 40);  // the streak crosses many pixels, not only where the sphere starts
}

}  // namespace

TEST(MotionBlur, AMovingSphereCoversEachPixelForTheFractionOfTheShutterItCrossesIt) {
    expect_coverage(WhittedIntegrator(), {0.0f, 1.0f});
    expect_coverage(PathIntegrator(), {0.0f, 1.0f});
}

TEST(MotionBlur, TheShutterChoosesTheStretchOfTheMotionSeen) {
    // Open for the middle half: the streak runs from x = −1 to 1 and is brighter.
    expect_coverage(WhittedIntegrator(), {0.25f, 0.75f});
}

TEST(MotionBlur, AnInstantShowsTheSphereSharpWhereItIsThen) {
    const Film film = render_blurred(moving_sphere_scene({0.5f, 0.5f}), WhittedIntegrator(), 4);
    // At time 0.5 the sphere is centred at x = 0: pixel 16 (x in [0, 0.25]) on the middle
    // rows is covered, pixel 6 (x in [−2.5, −2.25]) is not.
    EXPECT_FLOAT_EQ(film.at(16, 3).r, 1.0f);
    EXPECT_FLOAT_EQ(film.at(6, 3).r, 0.0f);
}

TEST(MotionBlur, AStaticSceneIgnoresTheShutterBitForBit) {
    // No time is drawn when nothing moves, so a shutter changes no sample of the image.
    Scene with_shutter = make_spheres_scene();
    with_shutter.camera.set_shutter({0.2f, 0.7f});
    ASSERT_FALSE(with_shutter.has_motion());
    // The path tracer: every sampler dimension after the camera's steers its paths.
    const Film plain = render_blurred(make_spheres_scene(), PathIntegrator(), 2);
    EXPECT_TRUE(same_pixels(plain, render_blurred(std::move(with_shutter), PathIntegrator(), 2)));
}

TEST(MotionBlur, OneAndTwoThreadsRenderTheSameImage) {
    const Film one = render_blurred(moving_sphere_scene({0.0f, 1.0f}), PathIntegrator(), 4, 1);
    const Film two = render_blurred(moving_sphere_scene({0.0f, 1.0f}), PathIntegrator(), 4, 2);
    EXPECT_TRUE(same_pixels(one, two));
}

TEST(MotionBlur, ShadowsFallWhereTheOccluderIsAtTheRaysTime) {
    // A ball moves from x = −2 to x = 2 at height 1 under a point light straight above
    // x = 2; the camera looks, below the ball, at the floor point under the light. At time 1
    // the ball shadows it, at time 0 it does not: shadow rays must travel at their camera
    // ray's time.
    auto scene_at = [](float time) {
        Scene scene;
        Material white;
        white.diffuse = Color(0.8f);
        const uint32_t floor = scene.add_material(white);
        scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, -10), Vec3(0, 0, 20), Vec3(20, 0, 0)), floor);
        const uint32_t ball = scene.add_object(std::make_shared<Sphere>(Vec3(0.0f), 0.5f), floor);
        scene.set_motion(ball, AnimatedTransform({{0.0f, Transform::translate({-2, 1, 0})},
                                                  {1.0f, Transform::translate({2, 1, 0})}}));
        scene.add_light(std::make_unique<PointLight>(Vec3(2, 10, 0), Color(100.0f), Falloff::InverseSquare));
        scene.camera = Camera::perspective({2, 0.2f, 5}, {2, 0, 0}, {0, 1, 0}, 10.0f);
        scene.camera.set_shutter({time, time});
        return scene;
    };
    for (const bool path : {false, true}) {
        const Film lit = path ? render_blurred(scene_at(0.0f), PathIntegrator(1), 1)
                              : render_blurred(scene_at(0.0f), WhittedIntegrator(), 1);
        const Film shadowed = path ? render_blurred(scene_at(1.0f), PathIntegrator(1), 1)
                                   : render_blurred(scene_at(1.0f), WhittedIntegrator(), 1);
        EXPECT_GT(lit.at(24, 18).r, 0.1f) << (path ? "path" : "whitted");
        EXPECT_EQ(shadowed.at(24, 18).r, 0.0f) << (path ? "path" : "whitted");
    }
}

TEST(MotionBlur, AnObjectThatLightsTheSceneCannotMove) {
    Scene scene;
    Material glow;
    glow.emission = Color(1.0f);
    const uint32_t object = scene.add_object(std::make_shared<Sphere>(Vec3(0.0f), 1.0f), scene.add_material(glow));
    EXPECT_THROW(
        scene.set_motion(object, AnimatedTransform({{0.0f, Transform()}, {1.0f, Transform::translate({1, 0, 0})}})),
        std::invalid_argument);
}

TEST(MotionBlur, AMovingCameraBlursAStaticScene) {
    Scene scene = make_spheres_scene();
    const Film still = render_blurred(make_spheres_scene(), WhittedIntegrator(), 2);
    scene.camera.set_motion({{0.0f, scene.camera.eye(), scene.camera.target()},
                             {1.0f, scene.camera.eye() + Vec3(3.0f, 0.0f, 0.0f), Vec3(3.0f, 2.0f, 0.0f)}});
    ASSERT_TRUE(scene.has_motion());
    EXPECT_FALSE(same_pixels(still, render_blurred(std::move(scene), WhittedIntegrator(), 2)));
}
