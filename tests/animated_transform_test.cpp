// Motion keys: interpolation against the transforms it must give, and motion bounds that
// hold every placement over the shutter.

#include "glint/math/animated_transform.h"
#include "glint/scene/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace glint;

namespace {

void expect_same_transform(const Transform& a, const Transform& b, float tolerance) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            EXPECT_NEAR(a.matrix().m[i][j], b.matrix().m[i][j], tolerance) << "entry " << i << "," << j;
}

bool contains(const Bounds3& outer, const Bounds3& inner) {
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

}  // namespace

TEST(AnimatedTransform, KeysHoldAtTheirTimesAndBeforeAndAfter) {
    const Transform a = Transform::translate({1, 2, 3});
    const Transform b = Transform::rotate(30.0f, {0, 0, 1}) * Transform::scale({2, 2, 2});
    const AnimatedTransform motion({{0.25f, a}, {0.75f, b}});
    EXPECT_EQ(motion.at(0.25f), a);
    EXPECT_EQ(motion.at(0.75f), b);
    EXPECT_EQ(motion.at(-5.0f), a);
    EXPECT_EQ(motion.at(9.0f), b);
}

TEST(AnimatedTransform, TranslationAndScaleAreLerpedRotationSlerped) {
    // Halfway from no turn to 90° about y is 45°, not the blend of the two matrices (which
    // would also shrink the object by cos 45°); scale 1 → 3 is 2, and translation halfway.
    const Transform start = Transform::translate({0, 0, 0});
    const Transform end =
        Transform::translate({4, 0, -2}) * Transform::rotate(90.0f, {0, 1, 0}) * Transform::scale({3, 3, 3});
    const AnimatedTransform motion({{0.0f, start}, {1.0f, end}});
    const Transform expected =
        Transform::translate({2, 0, -1}) * Transform::rotate(45.0f, {0, 1, 0}) * Transform::scale({2, 2, 2});
    expect_same_transform(motion.at(0.5f), expected, 2e-5f);
    // A quarter of the way along, at constant angular speed: 22.5°.
    const Transform quarter = Transform::translate({1, 0, -0.5f}) * Transform::rotate(22.5f, {0, 1, 0}) *
                              Transform::scale({1.5f, 1.5f, 1.5f});
    expect_same_transform(motion.at(0.25f), quarter, 2e-5f);
}

TEST(AnimatedTransform, AMirroredKeyKeepsItsMirror) {
    // A negative scale makes the polar factor a reflection; the decomposition moves the sign
    // to the stretch so that the rotation stays a rotation and the key comes back.
    const Transform mirrored = Transform::scale({-1, 1, 1});
    const Transform turned = Transform::rotate(60.0f, {1, 0, 0}) * mirrored;
    const AnimatedTransform motion({{0.0f, mirrored}, {1.0f, turned}});
    expect_same_transform(motion.at(0.5f), Transform::rotate(30.0f, {1, 0, 0}) * mirrored, 2e-5f);
    EXPECT_TRUE(motion.at(0.5f).swaps_handedness());
}

TEST(AnimatedTransform, EachTimeCarriesTheInverseOfItsTransform) {
    // Rays enter a moving object through the inverse, built from the parts (S⁻¹·Rᵀ·T⁻¹):
    // M·M⁻¹ must be the identity at every time, for a turn with a stretch that is not
    // uniform, for keys of another handedness than the first, and for three keys.
    const Transform start = Transform::translate({1, -2, 0.5f}) * Transform::scale({0.5f, 2, 1});
    const Transform end =
        Transform::translate({-3, 1, 2}) * Transform::rotate(130.0f, {1, 2, 0.5f}) * Transform::scale({3, 1, 0.25f});
    const Transform mirrored = Transform::rotate(40.0f, {0, 0, 1}) * Transform::scale({-1, 2, 1});
    const AnimatedTransform turning({{0.0f, start}, {1.0f, end}});
    const AnimatedTransform mirror({{0.0f, mirrored}, {1.0f, Transform::rotate(200.0f, {0, 1, 0}) * mirrored}});
    const AnimatedTransform three({{0.0f, start}, {0.5f, end}, {2.0f, Transform::translate({0, 4, 0})}});
    for (const AnimatedTransform* motion : {&turning, &mirror, &three})
        for (const float time : {0.1f, 0.37f, 0.5f, 0.9f, 1.4f}) {
            const Transform t = motion->at(time);
            const Matrix4 product = t.matrix() * t.inverse_matrix();
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    EXPECT_NEAR(product.m[i][j], i == j ? 1.0f : 0.0f, 2e-6f)
                        << "time " << time << ", entry " << i << "," << j;
        }
}

TEST(AnimatedTransform, AFlipThroughNoThicknessStaysFinite) {
    // Scale x from 1 to −1: the stretch blends through zero halfway, where the object is
    // flat. The transform at that instant stands for a time a step before, so that its
    // inverse exists (the matrix used to be inverted there, and had none).
    const AnimatedTransform flip({{0.0f, Transform()}, {1.0f, Transform::scale({-1, 1, 1})}});
    const Transform halfway = flip.at(0.5f);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            EXPECT_TRUE(std::isfinite(halfway.matrix().m[i][j])) << i << "," << j;
            EXPECT_TRUE(std::isfinite(halfway.inverse_matrix().m[i][j])) << i << "," << j;
        }
    EXPECT_NEAR(std::abs(halfway.point({1, 0, 0}).x) + std::abs(halfway.point({1, 0, 0}).y) +
                    std::abs(halfway.point({1, 0, 0}).z),
                0.0f, 1e-6f)
        << "flat at that instant";
}

TEST(SlerpArc, TurnsAtConstantSpeedAlongTheShorterArc) {
    // From no turn to 160° about an axis: each point is a unit quaternion at s·160° from the
    // start. The end given as −q (the same rotation) is reached the short way, not by 200°.
    const auto about = [](double degrees, double x, double y, double z) {
        const double half = degrees * 3.14159265358979323846 / 360.0, n = std::sqrt(x * x + y * y + z * z);
        return Quaternion{std::cos(half), std::sin(half) * x / n, std::sin(half) * y / n, std::sin(half) * z / n};
    };
    const Quaternion a = about(10.0, 0, 1, 0), b = about(170.0, 0, 1, 0);
    const Quaternion minus_b{-b.w, -b.x, -b.y, -b.z};
    const double radians = 3.14159265358979323846 / 180.0;
    for (const Quaternion& end : {b, minus_b}) {
        const SlerpArc arc(a, end);
        for (const double s : {0.0, 0.1, 0.25, 0.5, 0.8, 1.0}) {
            const Quaternion q = arc.at(s);
            EXPECT_NEAR(dot(q, q), 1.0, 1e-12) << "s " << s;
            EXPECT_NEAR(angle_between(a, q), s * 160.0 * radians, 1e-7) << "s " << s;
            EXPECT_NEAR(angle_between(q, b), (1.0 - s) * 160.0 * radians, 1e-7) << "s " << s;
        }
    }
    // Nearly the same rotation: the linear blend, normalised, halfway.
    const Quaternion near_a = about(11.0, 0, 1, 0);
    EXPECT_NEAR(angle_between(a, SlerpArc(a, near_a).at(0.5)), 0.5 * radians, 1e-7);
}

TEST(AnimatedTransform, BoundsHoldEveryPlacementOverTheInterval) {
    // A long box off the axis, half a turn, a translation and a growing scale: the middle
    // placements reach far outside the boxes at the two ends.
    const Bounds3 box({1.0f, -0.2f, -0.2f}, {3.0f, 0.2f, 0.2f});
    const AnimatedTransform motion({{0.0f, Transform()},
                                    {0.5f, Transform::rotate(90.0f, {0, 1, 0})},
                                    {1.0f, Transform::translate({0, 1, 0}) * Transform::rotate(179.0f, {0, 1, 0}) *
                                               Transform::scale({1.5f, 1, 1})}});
    for (const auto& [t0, t1] : {std::pair{0.0f, 1.0f}, std::pair{0.1f, 0.4f}, std::pair{0.3f, 0.8f}}) {
        const Bounds3 bounds = motion.bounds(box, t0, t1);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(t0, t1);
        for (int i = 0; i < 2000; ++i) {
            const float t = u(rng);
            ASSERT_TRUE(contains(bounds, motion.at(t).bounds(box)))
                << "time " << t << " in [" << t0 << ", " << t1 << "]";
        }
        // Not the whole turn's box when the interval is part of it: [0.1, 0.4] stays within
        // 0° to 72°, so nothing reaches x < 0.
        if (t1 <= 0.4f) {
            EXPECT_GT(bounds.lo.x, -0.5f);
        }
    }
}

TEST(AnimatedTransform, AnInstantIsBoundedByItsPlacement) {
    const Bounds3 box({-1, -1, -1}, {1, 1, 1});
    const AnimatedTransform motion({{0.0f, Transform()}, {1.0f, Transform::translate({10, 0, 0})}});
    const Bounds3 b = motion.bounds(box, 0.5f, 0.5f);
    EXPECT_FLOAT_EQ(b.lo.x, 4.0f);
    EXPECT_FLOAT_EQ(b.hi.x, 6.0f);
}

TEST(AnimatedTransform, RefusesKeysOutOfOrderAndASingleKey) {
    EXPECT_THROW(AnimatedTransform({{0.0f, Transform()}}), std::invalid_argument);
    EXPECT_THROW(AnimatedTransform({{0.5f, Transform()}, {0.5f, Transform()}}), std::invalid_argument);
    EXPECT_THROW(AnimatedTransform({{0.0f, Transform()}, {1.0f, Transform()}, {0.5f, Transform()}}),
                 std::invalid_argument);
}

TEST(CameraMotion, TheShutterGivesTimesAndRefusesClosingBeforeOpening) {
    Camera camera;
    camera.set_shutter({0.25f, 0.75f});
    EXPECT_FLOAT_EQ(camera.time(0.0f), 0.25f);
    EXPECT_FLOAT_EQ(camera.time(0.5f), 0.5f);
    EXPECT_FLOAT_EQ(camera.generate_ray(10, 10, 64, 64, {}, 0.6f).time, 0.6f);
    EXPECT_THROW(camera.set_shutter({0.5f, 0.25f}), std::invalid_argument);
}

TEST(CameraMotion, AMovingCameraIsOnItsLineAtEachTime) {
    Camera camera = Camera::perspective({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    camera.set_motion({{0.0f, {0, 0, 5}, {0, 0, 0}}, {1.0f, {2, 0, 5}, {2, 0, 0}}});
    const Ray start = camera.generate_ray(32, 32, 64, 64, {}, 0.0f);
    const Ray middle = camera.generate_ray(32, 32, 64, 64, {}, 0.5f);
    const Ray end = camera.generate_ray(32, 32, 64, 64, {}, 1.0f);
    EXPECT_FLOAT_EQ(start.origin.x, 0.0f);
    EXPECT_FLOAT_EQ(middle.origin.x, 1.0f);
    EXPECT_FLOAT_EQ(end.origin.x, 2.0f);
    EXPECT_NEAR(middle.direction.z, -1.0f, 1e-6f);
    // The eye passing through the target on the way is refused.
    Camera through = Camera::perspective({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    EXPECT_THROW(through.set_motion({{0.0f, {0, 0, 1}, {0, 0, 0}}, {1.0f, {0, 0, -1}, {0, 0, 0}}}),
                 std::invalid_argument);
}

TEST(CameraMotion, KeysAtAnyTimesMoveTheCameraPieceByPiece) {
    Camera camera = Camera::perspective({9, 9, 9}, {0, 0, 0}, {0, 1, 0}, 40.0f);
    camera.set_motion({{1.0f, {0, 0, 5}, {0, 0, 0}}, {3.0f, {4, 0, 5}, {4, 0, 0}}, {4.0f, {4, 2, 5}, {4, 2, 0}}});
    const auto eye_at = [&](float time) { return camera.generate_ray(32, 32, 64, 64, {}, time).origin; };
    EXPECT_EQ(camera.eye(), Vec3(0, 0, 5)) << "the first key is the camera's pose";
    EXPECT_EQ(eye_at(0.0f), Vec3(0, 0, 5)) << "held before the first key";
    EXPECT_EQ(eye_at(2.0f), Vec3(2, 0, 5));
    EXPECT_EQ(eye_at(3.5f), Vec3(4, 1, 5));
    EXPECT_EQ(eye_at(9.0f), Vec3(4, 2, 5)) << "held after the last";
    EXPECT_NEAR(camera.generate_ray(32, 32, 64, 64, {}, 3.5f).direction.z, -1.0f, 1e-6f);
    EXPECT_THROW(camera.set_motion({{0.0f, {0, 0, 5}, {0, 0, 0}}}), std::invalid_argument);
    EXPECT_THROW(camera.set_motion({{1.0f, {0, 0, 5}, {0, 0, 0}}, {1.0f, {1, 0, 5}, {0, 0, 0}}}),
                 std::invalid_argument);
}
