#include "glint/scene/asset_defaults.h"
#include "glint/scene/camera.h"
#include "glint/math/constants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace glint;

TEST(Camera, CentrePixelLooksAlongTheViewDirection) {
    const Camera cam = Camera::perspective({22, 24, 26}, {0, 2, 0}, {0, 1, 0}, 52.0f);
    const Ray r = cam.generate_ray(320.0f, 240.0f, 640, 480);
    const Vec3 expected = normalize(Vec3(0, 2, 0) - Vec3(22, 24, 26));
    EXPECT_NEAR(dot(r.direction, expected), 1.0f, 1e-6f);
    EXPECT_EQ(r.origin, Vec3(22, 24, 26));
}

// The render makes a packet's camera rays together (Camera::generate_rays) and explain()
// makes them one by one: both must be the same rays to the bit. An oblique view gives every
// product of the direction a part, so a product fused one way for one ray and another way
// for eight shows.
TEST(Camera, GenerateRaysMakesTheRaysOfGenerateRayBitForBit) {
    Camera lens = Camera::perspective({1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 35.0f);
    lens.set_lens(ThinLens{.aperture_radius = 0.1f, .focus_distance = 3.0f});
    Camera moving = Camera::perspective({22, 24, 26}, {0, 2, 0}, {0, 1, 0}, 52.0f);
    moving.set_motion({{0.0f, {22, 24, 26}, {0, 2, 0}}, {1.0f, {20, 24, 27}, {0, 2, 1}}});
    const Camera cameras[] = {Camera::perspective({22, 24, 26}, {0, 2, 0}, {0, 1, 0}, 52.0f),
                              Camera::perspective({-3, 0.5f, 7}, {1, 1, -2}, {0.2f, 1, 0}, 70.0f),
                              Camera::orthographic({5, 4, 3}, {0, 0, 0}, {0, 1, 0}, 6.0f), lens, moving};
    uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) * 0x1p-24f;
    };
    for (const Camera& camera : cameras)
        for (size_t count = 1; count <= 19; ++count) {  // whole batches of eight and a tail
            std::vector<Vec2> film(count), u_lens(count);
            std::vector<float> times(count);
            for (size_t k = 0; k < count; ++k) {
                film[k] = Vec2(next() * 640.0f, next() * 480.0f);
                u_lens[k] = Vec2(next(), next());
                times[k] = next();
            }
            std::vector<Ray> rays(count);
            camera.generate_rays(film, 640, 480, u_lens, times, rays);
            for (size_t k = 0; k < count; ++k) {
                const Ray one = camera.generate_ray(film[k].x, film[k].y, 640, 480, u_lens[k], times[k]);
                EXPECT_EQ(rays[k].origin, one.origin) << "ray " << k << " of " << count;
                EXPECT_EQ(rays[k].direction, one.direction) << "ray " << k << " of " << count;
                EXPECT_EQ(rays[k].time, one.time) << "ray " << k << " of " << count;
                EXPECT_EQ(rays[k].tmax, one.tmax);
            }
        }
}

TEST(Camera, EdgesMatchTheFieldOfView) {
    const float fov = 52.0f;
    const int w = 800, h = 400;
    const Camera cam = Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov);
    const Vec3 forward(0, 0, -1);
    // Top edge centre: half the vertical fov above the axis.
    const Ray top = cam.generate_ray(w / 2.0f, 0.0f, w, h);
    EXPECT_NEAR(std::acos(dot(top.direction, forward)), radians(fov / 2), 1e-5f);
    EXPECT_GT(top.direction.y, 0.0f);
    // Right edge centre: horizontal half-angle from tan = aspect · tan(fov/2).
    const Ray right = cam.generate_ray(float(w), h / 2.0f, w, h);
    EXPECT_NEAR(std::atan2(right.direction.x, -right.direction.z), std::atan(2.0f * std::tan(radians(fov / 2))), 1e-5f);
    // Corner: both offsets at once; (0,0) is the top-left.
    const Ray corner = cam.generate_ray(0.0f, 0.0f, w, h);
    const float t = std::tan(radians(fov / 2));
    const Vec3 expected = normalize(Vec3(-2.0f * t, t, -1));
    EXPECT_NEAR(dot(corner.direction, expected), 1.0f, 1e-6f);
}

TEST(Camera, UpVectorIsMadeOrthogonal) {
    const Camera cam = Camera::perspective({0, 0, 0}, {0, -1, -1}, {0, 1, 0}, 40.0f);
    EXPECT_NEAR(dot(cam.up(), cam.forward()), 0.0f, 1e-6f);
    EXPECT_NEAR(dot(cam.right(), cam.forward()), 0.0f, 1e-6f);
    EXPECT_GT(cam.up().y, 0.0f);
}

TEST(Camera, OrthographicRaysAreParallel) {
    const Camera cam = Camera::orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 4.0f);
    const Ray a = cam.generate_ray(0.0f, 0.0f, 100, 100), b = cam.generate_ray(100.0f, 100.0f, 100, 100);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_NEAR(a.origin.x, -2.0f, 1e-6f);
    EXPECT_NEAR(a.origin.y, 2.0f, 1e-6f);
    EXPECT_NEAR(b.origin.x, 2.0f, 1e-6f);
}

TEST(Camera, RejectsDegenerateSetups) {
    EXPECT_THROW((void)Camera::perspective({0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45.0f), std::invalid_argument);
    EXPECT_THROW((void)Camera::perspective({0, 0, 0}, {0, 5, 0}, {0, 1, 0}, 45.0f), std::invalid_argument);
    EXPECT_THROW((void)Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 180.0f), std::invalid_argument);
}

TEST(Camera, ProjectFindsThePixelWhoseRayPassesThroughAPoint) {
    const glint::Camera cameras[] = {
        glint::Camera::perspective({22, 24, 26}, {0, 2, 0}, {0, 1, 0}, 52.0f),
        glint::Camera::orthographic({0, 5, 10}, {0, 0, 0}, {0, 1, 0}, 6.0f),
    };
    for (const glint::Camera& camera : cameras)
        for (const auto& [x, y] : {std::pair{0.5f, 0.5f}, {320.0f, 240.0f}, {600.25f, 17.5f}, {3.0f, 470.0f}}) {
            const glint::Ray ray = camera.generate_ray(x, y, 640, 480);
            const std::optional<glint::Vec2> back = camera.project(ray.origin + ray.direction * 7.5f, 640, 480);
            ASSERT_TRUE(back.has_value());
            EXPECT_NEAR(back->x, x, 2e-3f);
            EXPECT_NEAR(back->y, y, 2e-3f);
        }
    EXPECT_FALSE(cameras[0].project({30, 30, 30}, 640, 480).has_value()) << "behind the eye";
}

TEST(FramingCamera, StandsTheUpAxisUprightOnScreen) {
    // A column 4 tall along the up axis and 0.5 wide: its top must project above its bottom,
    // on the same column of the image, with both ends in view.
    const std::pair<glint::UpAxis, glint::Vec3> axes[] = {
        {glint::UpAxis::X, {1, 0, 0}}, {glint::UpAxis::Y, {0, 1, 0}}, {glint::UpAxis::Z, {0, 0, 1}}};
    for (const auto& [axis, up] : axes) {
        const glint::Vec3 centre(3, -1, 2);
        const glint::Vec3 half = up * 2.0f + (glint::Vec3(1.0f) - up) * 0.25f;
        const glint::Camera camera =
            glint::framing_camera(glint::Bounds3(centre - half, centre + half), 4.0f / 3.0f, "column.ply", axis);
        const std::optional<glint::Vec2> top = camera.project(centre + up * 2.0f, 640, 480);
        const std::optional<glint::Vec2> bottom = camera.project(centre - up * 2.0f, 640, 480);
        ASSERT_TRUE(top && bottom);
        EXPECT_LT(top->y, bottom->y - 200.0f) << "the column stands upright and tall";
        EXPECT_NEAR(top->x, bottom->x, 1.0f);
        EXPECT_GT(top->y, 0.0f);
        EXPECT_LT(bottom->y, 480.0f);
    }
    EXPECT_EQ(glint::parse_up_axis("z"), glint::UpAxis::Z);
    EXPECT_FALSE(glint::parse_up_axis("-z"));
}
