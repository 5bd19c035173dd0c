// Depth of field: the thin-lens camera against the thin-lens formulas, ray by ray and in
// rendered images of a small emitter.

#include "chi2.h"

#include "glint/geometry/sphere.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/lights/light.h"
#include "glint/math/constants.h"
#include "glint/sampling/warp.h"
#include "glint/scene/camera.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace glint;

namespace {

constexpr float kFov = 40.0f;
constexpr int kFilmSide = 48;

Camera lens_camera(float aperture_radius, float focus_distance, uint32_t blades = 0) {
    Camera camera = Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, kFov);
    camera.set_lens({.aperture_radius = aperture_radius, .focus_distance = focus_distance, .blades = blades});
    return camera;
}

/// A small sphere of radiance 1 at `center` seen through `camera` on a black background,
/// kSide² pixels at samples_per_axis² samples each.
Film render_emitter(const Camera& camera, const Vec3& center, float radius, uint32_t samples_per_axis) {
    Scene scene;
    Material glow;
    glow.diffuse = Color(0.0f);
    glow.emission = Color(1.0f);
    scene.emission_lights = false;
    scene.add_object(std::make_shared<Sphere>(center, radius), scene.add_material(glow));
    scene.camera = camera;
    const RenderScene prepared(std::move(scene));
    RenderSettings settings;
    settings.width = settings.height = kFilmSide;
    settings.samples_per_axis = samples_per_axis;
    Film film(kFilmSide, kFilmSide);
    (void)WhittedIntegrator().render(prepared, settings, film);
    return film;
}

/// Radius in pixels of the bright disk of `film` around its centre: the area of the pixels
/// above half the plateau (the mean of the pixels within `inner` pixels of the centre).
float disk_radius(const Film& film, float inner) {
    const float c = 0.5f * float(kFilmSide);
    double plateau = 0.0;
    int inner_count = 0;
    for (int y = 0; y < kFilmSide; ++y)
        for (int x = 0; x < kFilmSide; ++x)
            if (std::hypot(float(x) + 0.5f - c, float(y) + 0.5f - c) < inner) {
                plateau += film.at(uint32_t(x), uint32_t(y)).r;
                ++inner_count;
            }
    plateau /= inner_count;
    int bright = 0;
    for (int y = 0; y < kFilmSide; ++y)
        for (int x = 0; x < kFilmSide; ++x) bright += film.at(uint32_t(x), uint32_t(y)).r > 0.5 * plateau;
    return std::sqrt(float(bright) / kPi);
}

/// The thin-lens circle of confusion of a point at depth z, in pixels of a kFilmSide-high image:
/// A·|1 − z_f/z| on the plane of focus, whose half-height z_f·tan(fov/2) is kFilmSide/2 pixels.
float circle_of_confusion_pixels(float aperture_radius, float focus_distance, float z) {
    const float on_focus_plane = aperture_radius * std::abs(1.0f - focus_distance / z);
    return on_focus_plane / (focus_distance * std::tan(radians(kFov) * 0.5f)) * (0.5f * float(kFilmSide));
}

}  // namespace

TEST(ThinLens, EveryLensRayMeetsThePinholeRayOnThePlaneOfFocus) {
    const float focus = 4.0f;
    const Camera pinhole = lens_camera(0.0f, focus);
    const Camera lens = lens_camera(0.3f, focus, 6);
    for (const Vec2 film : {Vec2(3.5f, 7.25f), Vec2(24.0f, 24.0f), Vec2(47.0f, 1.0f)}) {
        const Ray through = pinhole.generate_ray(film.x, film.y, kFilmSide, kFilmSide);
        const Vec3 target = through.at(focus / -through.direction.z);  // on the plane z = −focus
        for (const Vec2 u : {Vec2(0.1f, 0.9f), Vec2(0.5f, 0.5f), Vec2(0.99f, 0.02f)}) {
            const Ray r = lens.generate_ray(film.x, film.y, kFilmSide, kFilmSide, u);
            EXPECT_NEAR(length(r.direction), 1.0f, 1e-6f);
            EXPECT_NEAR(r.origin.z, 0.0f, 1e-6f);  // the aperture lies in the lens plane
            EXPECT_LE(std::hypot(r.origin.x, r.origin.y), 0.3f + 1e-6f);
            const Vec3 hit = r.at(focus / -r.direction.z);
            EXPECT_NEAR(length(hit - target), 0.0f, 2e-5f) << "film " << film.x << "," << film.y;
        }
    }
}

TEST(ThinLens, AZeroApertureIsThePinholeBitForBit) {
    const Camera plain = Camera::perspective({1, 2, 3}, {0, 0, -1}, {0, 1, 0}, 50.0f);
    Camera zero = plain;
    zero.set_lens({.aperture_radius = 0.0f, .focus_distance = 2.0f});
    for (const Vec2 u : {Vec2(0.3f, 0.7f), Vec2(0.9f, 0.1f)}) {
        const Ray a = plain.generate_ray(10.3f, 20.7f, 64, 48), b = zero.generate_ray(10.3f, 20.7f, 64, 48, u);
        EXPECT_EQ(a.origin, b.origin);
        EXPECT_EQ(a.direction, b.direction);
    }
}

TEST(ThinLens, RejectsANegativeApertureAndFocus) {
    Camera camera;
    EXPECT_THROW(camera.set_lens({.aperture_radius = -0.1f}), std::invalid_argument);
    EXPECT_THROW(camera.set_lens({.aperture_radius = 0.1f, .focus_distance = 0.0f}), std::invalid_argument);
}

TEST(ThinLens, TakesNoBladesOrThreeToTheMost) {
    // The aperture keeps a table of its corners: a count without bound would be memory
    // without bound.
    Camera camera;
    for (const uint32_t blades : {1u, 2u, ThinLens::kMaxBlades + 1, 1000000000u})
        EXPECT_THROW(camera.set_lens({.aperture_radius = 0.1f, .focus_distance = 1.0f, .blades = blades}),
                     std::invalid_argument)
            << blades;
    for (const uint32_t blades : {0u, 3u, ThinLens::kMaxBlades})
        EXPECT_NO_THROW(camera.set_lens({.aperture_radius = 0.1f, .focus_distance = 1.0f, .blades = blades})) << blades;
}

TEST(SamplingChi2, RegularPolygonAperture) {
    for (const uint32_t sides : {3u, 5u, 6u}) {
        const float rotation = 0.3f;
        // Inside a convex polygon: on the inner side of every edge.
        auto inside = [&](Vec2 p) {
            for (uint32_t k = 0; k < sides; ++k) {
                const float a0 = rotation + 2.0f * kPi * float(k) / float(sides);
                const float a1 = rotation + 2.0f * kPi * float(k + 1) / float(sides);
                const Vec2 v0(std::cos(a0), std::sin(a0)), v1(std::cos(a1), std::sin(a1));
                if ((v1.x - v0.x) * (p.y - v0.y) - (v1.y - v0.y) * (p.x - v0.x) < 0.0f) return false;
            }
            return true;
        };
        const double density = 1.0 / regular_polygon_area(sides);
        const UniformRegularPolygon polygon(sides, rotation);
        const Chi2Result r = chi2_planar_grid([&](Vec2 u) { return polygon.sample(u); },
                                              [&](Vec2 p) { return inside(p) ? density : 0.0; }, {-1.0f, -1.0f},
                                              {1.0f, 1.0f}, 20, 20, {500'000, 7, 0.01, 3});
        EXPECT_TRUE(r.passed) << sides << " sides: " << r.report;
    }
}

TEST(DepthOfField, APointOnThePlaneOfFocusLightsOnePixel) {
    const float focus = 5.0f;
    const Camera camera = lens_camera(0.25f, focus);
    // The point the centre of pixel (17, 30) sees on the plane of focus; the pixel spans
    // 2·5·tan 20°/48 ≈ 0.076 there, the sphere 0.02.
    const Ray through = lens_camera(0.0f, focus).generate_ray(17.5f, 30.5f, kFilmSide, kFilmSide);
    const Vec3 center = through.at(focus / -through.direction.z);
    const Film film = render_emitter(camera, center, 0.01f, 4);
    EXPECT_GT(film.at(17, 30).r, 0.0f);
    int lit = 0;
    for (uint32_t y = 0; y < kFilmSide; ++y)
        for (uint32_t x = 0; x < kFilmSide; ++x) lit += film.at(x, y).r > 0.0f;
    EXPECT_EQ(lit, 1);
}

TEST(DepthOfField, APointOffFocusBlursToTheCircleOfConfusion) {
    // A sphere 5 units away seen with the focus at 2.5 (behind the plane of focus) and at
    // 8 (in front of it): the disk of half brightness has the thin-lens radius within a
    // pixel. The sphere's own image (radius 0.1 at depth 5: 1.3 pixels) widens the edge
    // symmetrically about that radius.
    for (const auto& [aperture, focus] : {std::pair{0.6f, 2.5f}, std::pair{1.5f, 8.0f}}) {
        const float expected = circle_of_confusion_pixels(aperture, focus, 5.0f);
        ASSERT_GT(expected, 5.0f);
        ASSERT_LT(expected, 0.45f * kFilmSide);
        const Film film = render_emitter(lens_camera(aperture, focus), {0.0f, 0.0f, -5.0f}, 0.1f, 32);
        EXPECT_NEAR(disk_radius(film, 0.5f * expected), expected, 1.0f) << "focus " << focus;
    }
}

TEST(DepthOfField, BladesShapeTheBlurLikeTheirPolygon) {
    // Six blades: the blur is a hexagon inscribed in the round aperture's circle, so it
    // covers 3√3/(2π) ≈ 0.83 of the round blur's pixels.
    const float aperture = 0.6f, focus = 2.5f;
    const Film round = render_emitter(lens_camera(aperture, focus), {0.0f, 0.0f, -5.0f}, 0.1f, 32);
    const Film hexagon = render_emitter(lens_camera(aperture, focus, 6), {0.0f, 0.0f, -5.0f}, 0.1f, 32);
    const float inner = 0.4f * circle_of_confusion_pixels(aperture, focus, 5.0f);
    const float ratio = std::pow(disk_radius(hexagon, inner) / disk_radius(round, inner), 2.0f);
    EXPECT_NEAR(ratio, 3.0f * std::sqrt(3.0f) / (2.0f * kPi), 0.06f);
}

TEST(DepthOfField, OneAndTwoThreadsRenderTheSameImage) {
    Scene scene;
    Material grey;
    scene.add_object(std::make_shared<Sphere>(Vec3(0.3f, 0.0f, -4.0f), 1.0f), scene.add_material(grey));
    scene.add_object(std::make_shared<Sphere>(Vec3(-1.0f, 0.5f, -8.0f), 1.0f), scene.add_material(grey));
    scene.add_light(std::make_unique<PointLight>(Vec3(2, 3, 0), Color(10.0f), Falloff::InverseSquare));
    scene.camera = lens_camera(0.3f, 4.0f, 5);
    const RenderScene prepared(std::move(scene));
    RenderSettings settings;
    settings.width = settings.height = kFilmSide;
    settings.samples_per_axis = 3;
    auto render = [&](uint32_t threads) {
        settings.threads = threads;
        Film film(kFilmSide, kFilmSide);
        (void)WhittedIntegrator().render(prepared, settings, film);
        return film.to_image().pixels;
    };
    EXPECT_EQ(render(1), render(2));
}
