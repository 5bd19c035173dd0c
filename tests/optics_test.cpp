#include "glint/integrators/ior_stack.h"
#include "glint/materials/optics.h"
#include "glint/math/constants.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace glint;

TEST(Optics, ReflectionMirrorsAboutTheNormal) {
    const Vec3 i = normalize(Vec3(1, -1, 0));
    const Vec3 r = reflect(i, {0, 1, 0});
    EXPECT_NEAR(r.x, i.x, 1e-6f);
    EXPECT_NEAR(r.y, -i.y, 1e-6f);
    EXPECT_NEAR(length(r), 1.0f, 1e-6f);
}

TEST(Optics, RefractionObeysSnellsLaw) {
    const Vec3 n(0, 1, 0);
    for (float deg = 0.0f; deg < 89.0f; deg += 7.0f) {
        const float th = radians(deg);
        const Vec3 i(std::sin(th), -std::cos(th), 0);
        const auto t = refract(i, n, 1.0f, 1.5f);
        ASSERT_TRUE(t.has_value());
        EXPECT_NEAR(length(*t), 1.0f, 1e-5f);
        const float sin_t = std::sqrt(t->x * t->x + t->z * t->z);
        EXPECT_NEAR(1.0f * std::sin(th), 1.5f * sin_t, 1e-5f) << deg << " degrees";
        EXPECT_LT(t->y, 0.0f);                           // continues through the surface
        EXPECT_GE(t->x, 0.0f);                           // on the far side of the normal
        EXPECT_FLOAT_EQ(t->z, 0.0f);                     // stays in the plane of incidence
    }
}

TEST(Optics, TotalInternalReflectionBeyondTheCriticalAngle) {
    const Vec3 n(0, 1, 0);
    const float critical = critical_angle(1.5f, 1.0f);
    EXPECT_NEAR(critical, std::asin(1.0f / 1.5f), 1e-6f);
    const auto just_below = [&](float th) { return Vec3(std::sin(th), -std::cos(th), 0); };
    EXPECT_TRUE(refract(just_below(critical - 1e-3f), n, 1.5f, 1.0f).has_value());
    EXPECT_FALSE(refract(just_below(critical + 1e-3f), n, 1.5f, 1.0f).has_value());
    EXPECT_FLOAT_EQ(fresnel_schlick(just_below(critical + 1e-3f), n, 1.5f, 1.0f), 1.0f);
}

TEST(Optics, SchlickAtNormalAndGrazingIncidence) {
    const float n1 = 1.0f, n2 = 1.5f;
    const float r0 = std::pow((n1 - n2) / (n1 + n2), 2.0f);
    EXPECT_NEAR(schlick(1.0f, n1, n2), r0, 1e-7f);   // 0°: R0 = 0.04
    EXPECT_NEAR(r0, 0.04f, 1e-7f);
    EXPECT_NEAR(schlick(0.0f, n1, n2), 1.0f, 1e-7f);  // 90°
    // Head-on, both directions through the interface reflect the same.
    EXPECT_NEAR(fresnel_schlick({0, -1, 0}, {0, 1, 0}, 1.0f, 1.5f), r0, 1e-6f);
    EXPECT_NEAR(fresnel_schlick({0, -1, 0}, {0, 1, 0}, 1.5f, 1.0f), r0, 1e-6f);
    // Between the two ends, the fifth power: at 60°, R = R0 + (1 - R0)·0.5^5.
    EXPECT_NEAR(schlick(0.5f, n1, n2), r0 + (1.0f - r0) / 32.0f, 1e-7f);
    // Monotonic in angle.
    float last = 0.0f;
    for (float c = 1.0f; c >= 0.0f; c -= 0.05f) {
        const float f = schlick(c, n1, n2);
        EXPECT_GE(f, last);
        last = f;
    }
}

TEST(IorStack, NestedDielectrics) {
    IorStack air(1.0f);
    EXPECT_FLOAT_EQ(air.current(), 1.0f);
    const IorStack in_water = air.entered(7, 1.33f);
    EXPECT_FLOAT_EQ(in_water.current(), 1.33f);
    const IorStack in_glass = in_water.entered(9, 1.5f);
    EXPECT_FLOAT_EQ(in_glass.current(), 1.5f);
    // Leaving the glass returns to water, not to air.
    EXPECT_FLOAT_EQ(in_glass.outside_of(9), 1.33f);
    EXPECT_FLOAT_EQ(in_glass.left(9).current(), 1.33f);
    EXPECT_FLOAT_EQ(in_glass.left(9).left(7).current(), 1.0f);
}

TEST(IorStack, OverlappingExitOrder) {
    // Enter A then B, leave A first (overlapping volumes): we are then in B only.
    const IorStack s = IorStack(1.0f).entered(1, 1.2f).entered(2, 1.7f);
    EXPECT_FLOAT_EQ(s.outside_of(1), 1.0f);
    const IorStack after = s.left(1);
    EXPECT_FLOAT_EQ(after.current(), 1.7f);
    EXPECT_EQ(after.depth(), 1);
}

TEST(IorStack, MissedBoundariesKeepTheStackValid) {
    const IorStack air(1.0f);
    // Leaving a material never entered (its entry was missed): stay in the current medium.
    EXPECT_FLOAT_EQ(air.outside_of(5), 1.0f);
    EXPECT_EQ(air.left(5).depth(), 0);
    // Overflow drops the outermost entry and keeps the innermost ones.
    IorStack deep(1.0f);
    for (uint32_t i = 0; i < 20; ++i) deep = deep.entered(i, 1.0f + 0.01f * float(i));
    EXPECT_EQ(deep.depth(), IorStack::kCapacity);
    EXPECT_FLOAT_EQ(deep.current(), 1.19f);
}
