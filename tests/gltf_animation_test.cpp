// glTF node animations posed over the shutter (--time, --shutter): LINEAR, STEP and
// CUBICSPLINE samplers against their closed forms (glTF 2.0 Appendix C), rotations by
// slerp, animated parents, and the file loaded exactly as before without a shutter.

#include "gltf_animation_files.h"

#include "glint/assets/gltf_scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fs = std::filesystem;
using glint_test::AnimatedQuad;

namespace {

constexpr float kSqrtHalf = std::numbers::sqrt2_v<float> / 2.0f;

glint::GltfScene load_animated(const fs::path& path, std::optional<glint::Shutter> shutter) {
    glint::GltfOptions options;
    options.shutter = shutter;
    return glint::load_gltf_scene(path, options);
}

glint::Shutter instant(float t) { return {t, t}; }

/// A copy: the scene is often a temporary.
glint::SceneObject object(const glint::GltfScene& s, const std::string& name) {
    const auto& objects = s.loaded.scene.objects();
    const auto it = std::find_if(objects.begin(), objects.end(), [&](const auto& o) { return o.name == name; });
    if (it == objects.end()) throw std::runtime_error("no object " + name);
    return *it;
}

/// Where the object's origin is: at its one placement, or on its motion at `time`.
glint::Vec3 origin(const glint::SceneObject& o, float time = 0.0f) {
    return (o.motion ? o.motion->at(time) : o.world_from_object).point(glint::Vec3(0.0f));
}

bool has_line(const std::vector<std::string>& lines, const std::string& text) {
    return std::any_of(lines.begin(), lines.end(), [&](const auto& l) { return l.find(text) != std::string::npos; });
}

/// The quad translating along x from 0 at t = 0 to 2 at t = 1.
AnimatedQuad sliding_quad(const std::string& interpolation = "LINEAR") {
    AnimatedQuad quad;
    quad.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 2, 0, 0}, interpolation);
    return quad;
}

/// The quad turning from the identity to 90° about +y over t in [0, 1].
AnimatedQuad turning_quad(const std::string& interpolation = "LINEAR") {
    AnimatedQuad quad;
    if (interpolation == "CUBICSPLINE")  // zero tangents around each key
        quad.channel(0, "rotation", {0.0f, 1.0f},
                     {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, kSqrtHalf, 0, kSqrtHalf, 0, 0, 0, 0},
                     interpolation);
    else
        quad.channel(0, "rotation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, kSqrtHalf, 0, kSqrtHalf}, interpolation);
    return quad;
}

/// Expect `t` to be a rotation by `degrees` about +y: unit columns, no shrink.
void expect_turned(const glint::Transform& t, float degrees) {
    const float a = degrees * std::numbers::pi_v<float> / 180.0f;
    const auto& m = t.matrix().m;
    EXPECT_NEAR(m[0][0], std::cos(a), 1e-5f);
    EXPECT_NEAR(m[0][2], std::sin(a), 1e-5f);
    EXPECT_NEAR(m[2][0], -std::sin(a), 1e-5f);
    EXPECT_NEAR(m[2][2], std::cos(a), 1e-5f);
    EXPECT_NEAR(m[1][1], 1.0f, 1e-5f);
}

TEST(GltfAnimation, TimePosesTheNodeWithoutMotion) {
    const fs::path path = sliding_quad().write(glint_test::temp_dir(), "slide");
    const glint::GltfScene at_half = load_animated(path, instant(0.5f));
    const glint::SceneObject quad = object(at_half, "quad");
    EXPECT_FALSE(quad.motion);
    EXPECT_EQ(quad.world_from_object.matrix().m[0][3], 1.0f);  // exactly: (1 - ½)·0 + ½·2
    EXPECT_EQ(quad.world_bounds().lo.x, -9.0f);
    EXPECT_EQ(quad.world_bounds().hi.x, 11.0f);
    EXPECT_TRUE(has_line(at_half.report.mapped, "1 animation(s) posed at time 0.5"));
    EXPECT_FALSE(has_line(at_half.report.ignored, "animation"));
    // Held before the first key and after the last (§3.11).
    EXPECT_EQ(origin(object(load_animated(path, instant(-3.0f)), "quad")).x, 0.0f);
    EXPECT_EQ(origin(object(load_animated(path, instant(7.0f)), "quad")).x, 2.0f);
}

TEST(GltfAnimation, ShutterGivesTheMovingNodeMotionKeys) {
    const fs::path path = sliding_quad().write(glint_test::temp_dir(), "slide");
    const glint::GltfScene s = load_animated(path, glint::Shutter{0.0f, 1.0f});
    const glint::SceneObject quad = object(s, "quad");
    ASSERT_TRUE(quad.motion);
    EXPECT_EQ(quad.motion->keys().front().time, 0.0f);
    EXPECT_EQ(quad.motion->keys().back().time, 1.0f);
    EXPECT_GE(quad.motion->keys().size(), 17u);
    EXPECT_NEAR(origin(quad, 0.25f).x, 0.5f, 1e-6f);
    EXPECT_NEAR(origin(quad, 0.8f).x, 1.6f, 1e-6f);
    EXPECT_EQ(origin(quad, 0.0f).x, 0.0f);
    EXPECT_EQ(origin(quad, 1.0f).x, 2.0f);
    EXPECT_NEAR(quad.world_bounds().hi.x, 12.0f, 1e-5f);  // swept over the shutter
    EXPECT_TRUE(s.loaded.scene.has_motion());
    EXPECT_TRUE(has_line(s.report.mapped, "1 animation(s) sampled over the shutter [0, 1]"));
    EXPECT_TRUE(has_line(s.report.mapped, "1 object(s) move while the shutter is open"));
    // A shutter that sees only part of the keys: keyed over [0.25, 0.5].
    const glint::SceneObject part = object(load_animated(path, glint::Shutter{0.25f, 0.5f}), "quad");
    ASSERT_TRUE(part.motion);
    EXPECT_EQ(part.motion->keys().front().time, 0.25f);
    EXPECT_EQ(part.motion->keys().back().time, 0.5f);
    EXPECT_NEAR(origin(part, 0.375f).x, 0.75f, 1e-6f);
}

TEST(GltfAnimation, RotationIsSlerpedNotBlended) {
    const fs::path path = turning_quad().write(glint_test::temp_dir(), "turn");
    expect_turned(object(load_animated(path, instant(0.5f)), "quad").world_from_object, 45.0f);
    expect_turned(object(load_animated(path, instant(0.25f)), "quad").world_from_object, 22.5f);
    const glint::SceneObject moving = object(load_animated(path, glint::Shutter{0.0f, 1.0f}), "quad");
    ASSERT_TRUE(moving.motion);
    expect_turned(moving.motion->at(0.5f), 45.0f);
    expect_turned(moving.motion->at(0.3f), 27.0f);
}

TEST(GltfAnimation, StepHoldsThePreviousKey) {
    AnimatedQuad quad;
    quad.channel(0, "translation", {0.0f, 1.0f, 2.0f}, {0, 0, 0, 2, 0, 0, 4, 0, 0}, "STEP");
    const fs::path path = quad.write(glint_test::temp_dir(), "step");
    EXPECT_EQ(origin(object(load_animated(path, instant(0.99f)), "quad")).x, 0.0f);
    EXPECT_EQ(origin(object(load_animated(path, instant(1.0f)), "quad")).x, 2.0f);
    EXPECT_EQ(origin(object(load_animated(path, instant(1.5f)), "quad")).x, 2.0f);
    EXPECT_EQ(origin(object(load_animated(path, instant(2.5f)), "quad")).x, 4.0f);
    // Over a shutter across the jump: the old pose up to the key, the new one from it.
    const glint::SceneObject blurred = object(load_animated(path, glint::Shutter{0.5f, 1.5f}), "quad");
    ASSERT_TRUE(blurred.motion);
    EXPECT_EQ(origin(blurred, 0.999f).x, 0.0f);
    EXPECT_EQ(origin(blurred, 1.0f).x, 2.0f);
    EXPECT_EQ(origin(blurred, 1.3f).x, 2.0f);
}

TEST(GltfAnimation, CubicSplineIsTheHermiteCurve) {
    // Keys at t = 0 and 2 (t_d = 2): v0 = 0, v1 = 2 along x, out-tangent b0, in-tangent a1.
    auto x_at = [](float b0, float a1, float time) {
        AnimatedQuad quad;
        quad.channel(0, "translation", {0.0f, 2.0f}, {0, 0, 0, 0, 0, 0, b0, 0, 0, a1, 0, 0, 2, 0, 0, 0, 0, 0},
                     "CUBICSPLINE");
        const fs::path path = quad.write(glint_test::temp_dir(), "spline");
        return origin(object(load_animated(path, instant(time)), "quad")).x;
    };
    const double s = 0.25, td = 2.0;  // time 0.5
    const double h10 = s * s * s - 2 * s * s + s, h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
    EXPECT_NEAR(x_at(0.0f, 0.0f, 0.5f), h01 * 2.0, 1e-6);  // 0.3125, not the linear 0.5
    EXPECT_NEAR(x_at(1.0f, -1.0f, 0.5f), td * h10 * 1.0 + h01 * 2.0 + td * h11 * -1.0, 1e-6);
    EXPECT_NEAR(x_at(1.0f, -1.0f, 2.0f), 2.0f, 1e-6);  // the value at a key, not a tangent
    // A spline between rotations is normalised: with zero tangents the midpoint is half of
    // each key, a quaternion of length cos 22.5°, which unnormalised would shrink the quad.
    const fs::path turn = turning_quad("CUBICSPLINE").write(glint_test::temp_dir(), "turn");
    expect_turned(object(load_animated(turn, instant(0.5f)), "quad").world_from_object, 45.0f);
}

TEST(GltfAnimation, AnimatedParentMovesItsStaticChild) {
    AnimatedQuad quad;
    quad.json()["nodes"] = {{{"name", "parent"}, {"children", {1}}},
                            {{"name", "quad"}, {"mesh", 0}, {"translation", {1, 0, 0}}}};
    // The parent turns 90° about +y: the child, 1 away, moves on a quarter circle.
    quad.channel(0, "rotation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, kSqrtHalf, 0, kSqrtHalf});
    const fs::path path = quad.write(glint_test::temp_dir(), "parent");
    const glint::Vec3 at_half = origin(object(load_animated(path, instant(0.5f)), "quad"));
    EXPECT_NEAR(at_half.x, kSqrtHalf, 1e-5f);
    EXPECT_NEAR(at_half.z, -kSqrtHalf, 1e-5f);
    const glint::SceneObject moving = object(load_animated(path, glint::Shutter{0.0f, 1.0f}), "quad");
    ASSERT_TRUE(moving.motion);
    // Between motion keys the child goes on a chord: samples close enough keep it within
    // 0.1 % of the arc's radius anywhere over the shutter.
    for (float t = 0.0f; t <= 1.0f; t += 1.0f / 97.0f) {
        const glint::Vec3 p = origin(moving, t);
        EXPECT_NEAR(std::hypot(p.x, p.z), 1.0f, 1e-3f) << "t = " << t;
        EXPECT_NEAR(std::atan2(-p.z, p.x), t * std::numbers::pi_v<float> / 2.0f, 2e-3f) << "t = " << t;
    }
}

TEST(GltfAnimation, OnlyObjectsThatMoveGetMotion) {
    AnimatedQuad quad;
    quad.json()["nodes"] = {{{"name", "quad"}, {"mesh", 0}},
                            {{"name", "still"}, {"mesh", 0}, {"translation", {0, 5, 0}}}};
    quad.json()["scenes"][0]["nodes"] = {0, 1};
    quad.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 2, 0, 0});
    // Keys outside the shutter: the animation has ended and nothing moves.
    quad.channel(1, "translation", {-2.0f, -1.0f}, {0, 0, 0, 0, 5, 0});
    const glint::GltfScene s = load_animated(quad.write(glint_test::temp_dir(), "two"), glint::Shutter{0.0f, 1.0f});
    EXPECT_TRUE(object(s, "quad").motion);
    EXPECT_FALSE(object(s, "still").motion);
    EXPECT_EQ(origin(object(s, "still")).y, 5.0f);
}

TEST(GltfAnimation, WithoutAShutterTheFileLoadsAsBefore) {
    AnimatedQuad animated = sliding_quad();
    animated.json()["nodes"][0]["translation"] = {3, 0, 0};
    const fs::path dir = glint_test::temp_dir();
    const fs::path with = animated.write(dir, "with");
    AnimatedQuad still = animated;  // the same accessors and buffers
    still.json().erase("animations");
    const fs::path without = still.write(dir, "without");

    const glint::GltfScene a = load_animated(with, std::nullopt), b = load_animated(without, std::nullopt);
    ASSERT_EQ(a.loaded.scene.objects().size(), b.loaded.scene.objects().size());
    for (std::size_t i = 0; i < a.loaded.scene.objects().size(); ++i) {
        const glint::SceneObject &x = a.loaded.scene.objects()[i], &y = b.loaded.scene.objects()[i];
        EXPECT_EQ(x.world_from_object, y.world_from_object);
        EXPECT_EQ(x.has_transform, y.has_transform);
        EXPECT_FALSE(x.motion);
    }
    EXPECT_EQ(origin(object(a, "quad")).x, 3.0f);
    EXPECT_TRUE(has_line(a.report.ignored, "1 animation(s) (nodes drawn at their rest transforms)"));
    EXPECT_EQ(a.report.mapped, b.report.mapped);

    // A shutter changes nothing for a file without animations.
    const glint::GltfScene c = load_animated(without, glint::Shutter{0.0f, 1.0f});
    ASSERT_EQ(c.loaded.scene.objects().size(), b.loaded.scene.objects().size());
    for (std::size_t i = 0; i < b.loaded.scene.objects().size(); ++i)
        EXPECT_EQ(c.loaded.scene.objects()[i].world_from_object, b.loaded.scene.objects()[i].world_from_object);
    EXPECT_EQ(c.report.mapped, b.report.mapped);
    EXPECT_EQ(c.report.ignored, b.report.ignored);
}

TEST(GltfAnimation, CamerasLightsAndEmittersStayWhereTheyAreAtOpen) {
    AnimatedQuad quad;
    auto& json = quad.json();
    json["nodes"].push_back({{"name", "cam"}, {"camera", 0}, {"translation", {0, 5, 0}}});
    json["nodes"].push_back({{"name", "lamp"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    json["scenes"][0]["nodes"] = {0, 1, 2};
    json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}}};
    json["materials"][0]["emissiveFactor"] = {1, 1, 1};
    quad.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 2, 0, 0});
    quad.channel(1, "translation", {0.0f, 1.0f}, {0, 5, 0, 1, 5, 0});
    quad.channel(2, "translation", {0.0f, 1.0f}, {0, 3, 0, 0, 4, 0});
    const glint::GltfScene s = load_animated(quad.write(glint_test::temp_dir(), "rig"), glint::Shutter{0.5f, 1.0f});
    EXPECT_NEAR(s.loaded.scene.camera.eye().x, 0.5f, 1e-6f);
    EXPECT_FALSE(s.loaded.scene.camera.moves());
    EXPECT_TRUE(has_line(s.report.ignored, "camera animation blur"));
    EXPECT_TRUE(has_line(s.report.ignored, "light animation"));
    // The emissive quad lights the scene: it stays where it is at open.
    EXPECT_FALSE(object(s, "quad").motion);
    EXPECT_EQ(origin(object(s, "quad")).x, 1.0f);
    EXPECT_TRUE(has_line(s.report.ignored, "animation of an object that lights the scene"));
}

}  // namespace
