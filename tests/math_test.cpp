#include "glint/math/bounds3.h"
#include "glint/math/color.h"
#include "glint/math/divisor.h"
#include "glint/math/frame.h"
#include "glint/math/matrix3x4.h"
#include "glint/math/offset_ray.h"
#include "glint/math/transform.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace glint;

namespace {

void expect_near(const Vec3& a, const Vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(Transform, TranslateMovesPointsNotVectors) {
    const Transform t = Transform::translate({1, 2, 3});
    expect_near(t.point({0, 0, 0}), {1, 2, 3});
    expect_near(t.vector({1, 0, 0}), {1, 0, 0});
}

TEST(Transform, RotateIsCounterClockwiseAboutAxis) {
    const Transform r = Transform::rotate(90.0f, {0, 1, 0});
    // Right-handed: +x turns towards -z about +y.
    expect_near(r.vector({1, 0, 0}), {0, 0, -1});
    expect_near(Transform::rotate(90.0f, {0, 0, 1}).vector({1, 0, 0}), {0, 1, 0});
}

TEST(Transform, InverseUndoesComposite) {
    const Transform t =
        Transform::translate({1, -2, 3}) * Transform::rotate(33.0f, {1, 1, 0}) * Transform::scale({2, 0.5f, 3});
    const Vec3 p(0.3f, -1.2f, 4.0f);
    expect_near(t.inverse().point(t.point(p)), p, 1e-4f);
    expect_near((t * t.inverse()).point(p), p, 1e-4f);
}

TEST(Transform, CompositionAppliesRightOperandFirst) {
    const Transform t = Transform::translate({10, 0, 0}) * Transform::scale({2, 2, 2});
    expect_near(t.point({1, 0, 0}), {12, 0, 0});
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
    const Transform s = Transform::scale({4, 1, 1});
    // The plane x + y = 1 has normal (1,1,0) and tangent (1,-1,0).
    const Vec3 tangent = s.vector({1, -1, 0});
    const Vec3 n = s.normal({1, 1, 0});
    EXPECT_NEAR(dot(tangent, n), 0.0f, 1e-6f);
    // A naive vector transform would not be perpendicular.
    EXPECT_GT(std::abs(dot(tangent, s.vector({1, 1, 0}))), 1.0f);
}

TEST(Transform, SingularMatrixIsRejected) {
    Matrix4 m = Matrix4::identity();
    m.m[1][1] = 0.0f;
    EXPECT_THROW(Transform{m}, std::invalid_argument);
    EXPECT_THROW((void)Transform::scale({1, 0, 1}), std::invalid_argument);
}

TEST(Transform, BoundsContainTransformedCorners) {
    const Transform r = Transform::rotate(45.0f, {0, 0, 1});
    const Bounds3 b = r.bounds(Bounds3({-1, -1, -1}, {1, 1, 1}));
    EXPECT_NEAR(b.hi.x, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(b.lo.y, -std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(b.hi.z, 1.0f, 1e-6f);
}

TEST(Transform, HandednessSwapIsDetected) {
    EXPECT_TRUE(Transform::scale({-1, 1, 1}).swaps_handedness());
    EXPECT_FALSE(Transform::rotate(120.0f, {1, 2, 3}).swaps_handedness());
}

// The top level keeps each object's inverse as a Matrix3x4: a ray it moves into object
// space must be the one Transform::ray gives, bit for bit (the images depend on it), for
// any composition of steps a scene file can write.
TEST(Matrix3x4, MovesRaysExactlyAsTheTransform) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    for (int i = 0; i < 1000; ++i) {
        const Transform t = Transform::translate({u(rng), u(rng), u(rng)}) *
                            Transform::rotate(60.0f * u(rng), {u(rng), u(rng), u(rng) + 7.0f}) *
                            Transform::scale({u(rng) + 3.5f, -u(rng) - 3.5f, 0.25f});
        const Transform inv = t.inverse();
        ASSERT_TRUE(inv.matrix().is_affine());
        const Ray r({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, 0.001f, 50.0f, 0.5f);
        const Ray expected = inv.ray(r);
        const Ray got = Matrix3x4::of(inv.matrix()).ray(r);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(got.origin[k], expected.origin[k]) << "ray " << i;
            ASSERT_EQ(got.direction[k], expected.direction[k]) << "ray " << i;
        }
        EXPECT_EQ(got.tmin, r.tmin);
        EXPECT_EQ(got.tmax, r.tmax);
        EXPECT_EQ(got.time, r.time);
    }
}

TEST(Matrix4, AffineMeansTheLastRowIsExactly0001) {
    EXPECT_TRUE(Matrix4::identity().is_affine());
    EXPECT_TRUE((Transform::rotate(30.0f, {1, 1, 0}) * Transform::translate({1, 2, 3})).inverse_matrix().is_affine());
    Matrix4 m = Matrix4::identity();
    m.m[3][0] = 0.5f;
    EXPECT_FALSE(m.is_affine());
    m = Matrix4::identity();
    m.m[3][3] = 2.0f;
    EXPECT_FALSE(m.is_affine());
}

TEST(Bounds3, SlabTestHitMissAndInside) {
    const Bounds3 box({-1, -1, -1}, {1, 1, 1});
    float t0, t1;
    const Vec3 d(1, 0, 0);
    const Vec3 inv(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
    ASSERT_TRUE(box.intersect({-5, 0, 0}, inv, 0.0f, kInfinity, t0, t1));
    EXPECT_FLOAT_EQ(t0, 4.0f);
    EXPECT_FLOAT_EQ(t1, 6.0f);
    EXPECT_FALSE(box.intersect({-5, 2, 0}, inv, 0.0f, kInfinity, t0, t1));
    EXPECT_FALSE(box.intersect({-5, 0, 0}, inv, 0.0f, 3.0f, t0, t1));     // box beyond tmax
    ASSERT_TRUE(box.intersect({0, 0, 0}, inv, 0.0f, kInfinity, t0, t1));  // from inside
    EXPECT_FLOAT_EQ(t0, 0.0f);
    EXPECT_FLOAT_EQ(t1, 1.0f);
}

TEST(Bounds3, EmptyBoxHasNoArea) {
    Bounds3 b;
    EXPECT_TRUE(b.empty());
    EXPECT_EQ(b.half_area(), 0.0f);
    b.extend(Vec3(1, 2, 3));
    EXPECT_FALSE(b.empty());
    EXPECT_TRUE(b.contains({1, 2, 3}));
}

TEST(Frame, OrthonormalForRandomNormals) {
    std::mt19937 rng(7);
    std::normal_distribution<float> g;
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = normalize(Vec3(g(rng), g(rng), g(rng)));
        Vec3 b1, b2;
        orthonormal_basis(n, b1, b2);
        EXPECT_NEAR(length(b1), 1.0f, 1e-5f);
        EXPECT_NEAR(length(b2), 1.0f, 1e-5f);
        EXPECT_NEAR(dot(b1, n), 0.0f, 1e-5f);
        EXPECT_NEAR(dot(b2, n), 0.0f, 1e-5f);
        EXPECT_NEAR(dot(b1, b2), 0.0f, 1e-5f);
        expect_near(cross(b1, b2), n, 1e-4f);
    }
}

TEST(OffsetRay, MovesToTheNormalSideAtEveryScale) {
    for (float scale : {1e-3f, 1.0f, 1e3f, 1e6f}) {
        const Vec3 p(scale * 0.7f, -scale * 1.3f, scale * 0.2f);
        const Vec3 n = normalize(Vec3(1, 2, -1));
        const Vec3 o = offset_ray_origin(p, n);
        EXPECT_GT(dot(o - p, n), 0.0f) << "scale " << scale;
        // Small relative to the coordinates: a few thousand float ulps at most.
        EXPECT_LT(length(o - p), 1e-3f * std::max(1.0f, scale)) << "scale " << scale;
    }
}

TEST(OffsetRay, ABrokenNormalMovesThePointAtMostALittle) {
    // Degenerate input geometry gives NaN or infinite normals; the offset must stay a few
    // hundred ulps (an unclamped conversion made it INT_MIN and flipped the sign of p).
    const float inf = std::numeric_limits<float>::infinity();
    const Vec3 p(1.5f, -2.0f, 300.0f);
    const Vec3 o = offset_ray_origin(p, Vec3(std::numeric_limits<float>::quiet_NaN(), inf, -inf));
    for (int a = 0; a < 3; ++a) {
        EXPECT_TRUE(std::isfinite(o[a])) << a;
        EXPECT_LE(std::abs(o[a] - p[a]), 1e-3f * std::abs(p[a])) << a;
    }
}

TEST(Color, SrgbRoundTripAndKnownValues) {
    EXPECT_NEAR(srgb_to_linear(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgb_to_linear(0.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(srgb_to_linear(0.5f), 0.21404f, 1e-4f);  // IEC 61966-2-1
    for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(linear_to_srgb(srgb_to_linear(v)), v, 1e-5f);
}

TEST(Divisor, GivesWhatDivisionGivesBitForBit) {
    // Powers of two (the shift, mask and product) and others (the divisions), small and large.
    std::vector<uint32_t> divisors;
    for (uint32_t d = 1; d <= 70; ++d) divisors.push_back(d);
    for (const uint32_t d : {1u << 20, 1u << 31, 3u << 20, 4095u, 0xffffffffu}) divisors.push_back(d);
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> any_uint;
    // Floats of every magnitude the bits allow (subnormals included), and the samplers'
    // stratum plus jitter.
    std::vector<float> xs = {0.0f,
                             1.0f,
                             0x1.fffffep-1f,
                             63.999996f,
                             std::numeric_limits<float>::denorm_min(),
                             std::numeric_limits<float>::min(),
                             std::numeric_limits<float>::max()};
    for (int k = 0; k < 2000; ++k) {
        const float x = std::bit_cast<float>(any_uint(rng) & 0x7fffffffu);
        if (std::isfinite(x)) xs.push_back(x);
        xs.push_back(float(k % 64) + std::uniform_real_distribution<float>(0.0f, 1.0f)(rng));
    }
    for (const uint32_t d : divisors) {
        const Divisor by(d);
        EXPECT_EQ(by.value(), d);
        for (uint32_t k = 0; k < 3000; ++k) {
            const uint32_t i = k < 1000 ? k : k < 1010 ? 0xffffffffu - (k - 1000) : any_uint(rng);
            ASSERT_EQ(by.quotient(i), i / d) << i << " / " << d;
            ASSERT_EQ(by.remainder(i), i % d) << i << " % " << d;
        }
        for (const float x : xs)
            ASSERT_EQ(std::bit_cast<uint32_t>(by.divide(x)), std::bit_cast<uint32_t>(x / float(d))) << x << " / " << d;
    }
}
