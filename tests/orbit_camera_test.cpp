// The viewer's orbit camera (glint/scene/orbit_camera.h): it starts where the scene camera
// is, turns about its target at a fixed distance, frames a box to fill the field of view, and
// prints a [camera] table that a scene file reads back as the same view.
#include "glint/scene/orbit_camera.h"

#include "glint/math/constants.h"
#include "glint/scene_file.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using glint::Vec3;

void expect_point_near(const Vec3& a, const Vec3& b, float tolerance, const char* what) {
    EXPECT_NEAR(a.x, b.x, tolerance) << what;
    EXPECT_NEAR(a.y, b.y, tolerance) << what;
    EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

const glint::Camera kSeminar = glint::Camera::perspective({22, 24, 26}, {0, 2, 0}, {0, 1, 0}, 52.0f);

}  // namespace

TEST(OrbitCamera, StartsWhereTheSceneCameraIs) {
    const float d = glint::length(Vec3(22, 22, 26));
    const glint::OrbitCamera orbit = glint::OrbitCamera::from(kSeminar, d);
    const glint::Camera c = orbit.camera();
    expect_point_near(c.eye(), kSeminar.eye(), 1e-4f, "eye");
    expect_point_near(c.forward(), kSeminar.forward(), 1e-6f, "forward");
    expect_point_near(c.up(), kSeminar.up(), 1e-6f, "up");
    expect_point_near(orbit.target(), Vec3(0, 2, 0), 1e-4f, "target");
}

TEST(OrbitCamera, OrbitingKeepsTheDistanceAndAFullTurnComesBack) {
    glint::OrbitCamera orbit = glint::OrbitCamera::from(kSeminar, 10.0f);
    const Vec3 start = orbit.eye();
    orbit.orbit(0.7f, 0.2f);
    EXPECT_NEAR(glint::length(orbit.eye() - orbit.target()), 10.0f, 1e-4f);
    EXPECT_GT(glint::length(orbit.eye() - start), 1.0f);
    orbit.orbit(-0.7f, -0.2f);
    expect_point_near(orbit.eye(), start, 1e-4f, "back");
    orbit.orbit(2.0f * glint::kPi, 0.0f);
    expect_point_near(orbit.eye(), start, 1e-4f, "full turn");
}

TEST(OrbitCamera, PitchStopsShortOfTheZenith) {
    glint::OrbitCamera orbit = glint::OrbitCamera::from(kSeminar, 10.0f);
    orbit.orbit(0.0f, 10.0f);
    const Vec3 to_eye = glint::normalize(orbit.eye() - orbit.target());
    EXPECT_NEAR(std::asin(to_eye.y), 89.0f * glint::kPi / 180.0f, 1e-4f);
    EXPECT_TRUE(std::isfinite(orbit.camera().right().x));
}

TEST(OrbitCamera, PanMovesEyeAndTargetTogetherAndDollyScalesTheDistance) {
    glint::OrbitCamera orbit = glint::OrbitCamera::from(kSeminar, 10.0f);
    const Vec3 eye = orbit.eye(), target = orbit.target(), right = orbit.camera().right();
    orbit.pan(0.5f, 0.0f);
    expect_point_near(orbit.target() - target, right * 5.0f, 1e-4f, "target moves right by half the distance");
    expect_point_near(orbit.eye() - eye, right * 5.0f, 1e-4f, "eye moves with it");
    orbit.dolly(0.5f);
    EXPECT_NEAR(orbit.distance(), 5.0f, 1e-5f);
}

TEST(OrbitCamera, FrameFitsTheBoundingSphereInTheFieldOfView) {
    glint::OrbitCamera orbit = glint::OrbitCamera::from(kSeminar, 10.0f);
    const glint::Bounds3 box({-1, -2, -3}, {3, 2, 1});
    orbit.frame(box);
    expect_point_near(orbit.target(), Vec3(1, 0, -1), 1e-5f, "centre");
    const float radius = 0.5f * glint::length(box.diagonal());
    EXPECT_NEAR(orbit.distance() * std::sin(26.0f * glint::kPi / 180.0f), radius, 1e-4f);
    expect_point_near(orbit.camera().forward(), kSeminar.forward(), 1e-5f, "direction kept");
}

TEST(OrbitCamera, AZUpCameraOrbitsAboutZ) {
    const glint::Camera z_up = glint::Camera::perspective({5, -5, 3}, {0, 0, 0}, {0, 0, 1}, 40.0f);
    glint::OrbitCamera orbit = glint::OrbitCamera::from(z_up, glint::length(Vec3(5, -5, 3)));
    const float height = orbit.eye().z;
    orbit.orbit(1.0f, 0.0f);
    EXPECT_NEAR(orbit.eye().z, height, 1e-4f);
}

TEST(OrbitCamera, ThePrintedTableIsReadBackAsTheSameView) {
    glint::OrbitCamera orbit = glint::OrbitCamera::from(kSeminar, 12.0f);
    orbit.orbit(0.4f, -0.1f);
    orbit.pan(0.1f, 0.05f);
    const std::filesystem::path dir = glint_test::temp_dir();
    glint_test::write_file(dir / "view.toml", orbit.toml() + R"(
[[materials]]
name = "grey"

[[objects]]
type = "sphere"
center = [0, 0, 0]
radius = 1
material = "grey"
)");
    const glint::SceneFile file = glint::load_scene_file(dir / "view.toml");
    const glint::Camera& back = file.loaded.scene.camera;
    expect_point_near(back.eye(), orbit.eye(), 1e-4f, "eye");
    expect_point_near(back.forward(), orbit.camera().forward(), 1e-5f, "forward");
    EXPECT_EQ(back.vertical_fov(), 52.0f);
    std::filesystem::remove_all(dir);
}

TEST(OrbitCamera, KeepsTheLensAndPrintsIt) {
    glint::Camera lens_camera = kSeminar;
    lens_camera.set_lens({.aperture_radius = 0.3f, .focus_distance = 20.0f, .blades = 6, .rotation = 10.0f});
    glint::OrbitCamera orbit = glint::OrbitCamera::from(lens_camera, 12.0f);
    orbit.orbit(0.4f, -0.1f);
    const glint::ThinLens lens = orbit.camera().lens();
    EXPECT_EQ(lens.aperture_radius, 0.3f);
    EXPECT_EQ(lens.focus_distance, 20.0f);
    EXPECT_EQ(lens.blades, 6u);
    const std::filesystem::path dir = glint_test::temp_dir();
    glint_test::write_file(
        dir / "lens.toml",
        orbit.toml() +
            "[[materials]]\nname = \"grey\"\n\n[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"grey\"\n");
    const glint::ThinLens back = glint::load_scene_file(dir / "lens.toml").loaded.scene.camera.lens();
    EXPECT_EQ(back.aperture_radius, 0.3f);
    EXPECT_EQ(back.focus_distance, 20.0f);
    EXPECT_EQ(back.blades, 6u);
    EXPECT_EQ(back.rotation, 10.0f);
    std::filesystem::remove_all(dir);
}
