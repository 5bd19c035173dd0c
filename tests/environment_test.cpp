// Environment maps: the six axis directions land on the right texels of equirectangular,
// mirror-ball and angular maps, uv ↔ direction round trips (docs/units.md, conventions in scene/background.h), rotation and scale,
// and the shared HDR files load and agree with each other.

#include "glint/image/image_io.h"
#include "glint/scene/environment.h"
#include "glint/scene/background.h"

#include "source_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace {

using glint::Vec2;
using glint::Vec3;

void expect_uv(const Vec2& uv, float u, float v) {
    EXPECT_NEAR(uv.x, u, 1e-5f);
    EXPECT_NEAR(uv.y, v, 1e-5f);
}

TEST(EnvironmentLookup, EquirectangularAxes) {
    expect_uv(glint::equirectangular_uv(Vec3(0, 0, -1)), 0.5f, 0.5f);   // centre column looks along -z
    expect_uv(glint::equirectangular_uv(Vec3(1, 0, 0)), 0.75f, 0.5f);   // +x to its right
    expect_uv(glint::equirectangular_uv(Vec3(-1, 0, 0)), 0.25f, 0.5f);
    EXPECT_NEAR(std::fmod(glint::equirectangular_uv(Vec3(0, 0, 1)).x, 1.0f), 0.0f, 1e-5f);  // the seam
    EXPECT_NEAR(glint::equirectangular_uv(Vec3(0, 1, 0)).y, 0.0f, 1e-5f);   // +y top row
    EXPECT_NEAR(glint::equirectangular_uv(Vec3(0, -1, 0)).y, 1.0f, 1e-5f);  // -y bottom row
}

TEST(EnvironmentLookup, SphereMapAxes) {
    expect_uv(glint::sphere_map_uv(Vec3(0, 0, 1)), 0.5f, 0.5f);  // centre shows +z (towards the viewer)
    const float r = std::sqrt(0.5f);                             // 90° away: ball normal at 45°
    expect_uv(glint::sphere_map_uv(Vec3(1, 0, 0)), 0.5f + 0.5f * r, 0.5f);
    expect_uv(glint::sphere_map_uv(Vec3(-1, 0, 0)), 0.5f - 0.5f * r, 0.5f);
    expect_uv(glint::sphere_map_uv(Vec3(0, 1, 0)), 0.5f, 0.5f - 0.5f * r);  // +y up in the image
    expect_uv(glint::sphere_map_uv(Vec3(0, -1, 0)), 0.5f, 0.5f + 0.5f * r);
    const Vec2 back = glint::sphere_map_uv(Vec3(0, 0, -1));                // -z is the rim
    EXPECT_NEAR(std::hypot(back.x - 0.5f, back.y - 0.5f), 0.5f, 1e-5f);
}

/// An image whose every texel encodes its own coordinates: red = x, green = y.
std::shared_ptr<const glint::Image> coordinate_image(int w, int h) {
    glint::Image img(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            img.at(x, y, 0) = float(x);
            img.at(x, y, 1) = float(y);
        }
    return std::make_shared<const glint::Image>(std::move(img));
}

/// Where a lookup lands, in continuous texel coordinates: the coordinate image is looked up
/// bilinearly, so the colour is the lookup position (texel centres at integer values).
void expect_lookup(const glint::Background& bg, const Vec3& d, float x, float y) {
    const glint::Color c = bg.evaluate(d);
    EXPECT_NEAR(c.r, x, 1e-3f) << "direction " << d;
    EXPECT_NEAR(c.g, y, 1e-3f) << "direction " << d;
}

TEST(EnvironmentLookup, SixAxesLandOnTheRightEquirectTexels) {
    // 64×32 map: u = 0.5 + atan2(x, -z)/2π, v = acos(y)/π; position = uv·size - 0.5.
    const auto bg = glint::Background::environment(glint::BackgroundKind::Equirectangular, coordinate_image(64, 32));
    expect_lookup(bg, Vec3(0, 0, -1), 31.5f, 15.5f);  // centre column looks along -z
    expect_lookup(bg, Vec3(1, 0, 0), 47.5f, 15.5f);   // +x a quarter turn to the right
    expect_lookup(bg, Vec3(-1, 0, 0), 15.5f, 15.5f);
    // +z is the seam: longitude wraps, blending the last and first columns (63 and 0).
    expect_lookup(bg, Vec3(0, 0, 1), 31.5f, 15.5f);
    EXPECT_NEAR(bg.evaluate(Vec3(0, 1, 0)).g, 0.0f, 1e-3f);    // +y: top row (clamped)
    EXPECT_NEAR(bg.evaluate(Vec3(0, -1, 0)).g, 31.0f, 1e-3f);  // -y: bottom row (clamped)
}

TEST(EnvironmentLookup, SixAxesLandOnTheRightSphereMapTexels) {
    // 64×64 mirror ball seen from +z: direction d shows at the ball normal normalize(d + z),
    // so the axes ±x, ±y land at √½ of the radius from the centre, -z on the rim.
    const auto bg = glint::Background::environment(glint::BackgroundKind::SphereMap, coordinate_image(64, 64));
    const float r = std::sqrt(0.5f);
    auto pos = [](float unit) { return 32.0f * (1.0f + unit) - 0.5f; };  // [-1,1] → texel coordinate
    expect_lookup(bg, Vec3(0, 0, 1), pos(0), pos(0));
    expect_lookup(bg, Vec3(1, 0, 0), pos(r), pos(0));
    expect_lookup(bg, Vec3(-1, 0, 0), pos(-r), pos(0));
    expect_lookup(bg, Vec3(0, 1, 0), pos(0), pos(-r));  // +y up: towards the top row
    expect_lookup(bg, Vec3(0, -1, 0), pos(0), pos(r));
    expect_lookup(bg, Vec3(0, 0, -1), 63.0f, pos(0));   // the rim (clamped at the border)
}

TEST(EnvironmentLookup, RotationTurnsTheMapAboutYAndScaleMultiplies) {
    // Turned by +90° (counter-clockwise from above), what was at -z is now seen towards -x.
    const auto img = coordinate_image(64, 32);
    const auto turned = glint::Background::environment(glint::BackgroundKind::Equirectangular, img, 90.0f, 2.0f);
    const auto plain = glint::Background::environment(glint::BackgroundKind::Equirectangular, img);
    EXPECT_EQ(turned.evaluate(Vec3(-1, 0, 0)).r, 2.0f * plain.evaluate(Vec3(0, 0, -1)).r);
}

TEST(EnvironmentLookup, AngularMapAxesLandOnTheRightTexels) {
    // 64×64 angular map (Debevec): the centre looks along -z, the radius is the angle from -z
    // over π, so the axes ±x, ±y (90° away) land half way out and +z on the rim.
    const auto bg = glint::Background::environment(glint::BackgroundKind::AngularMap, coordinate_image(64, 64));
    auto pos = [](float unit) { return 32.0f * (1.0f + unit) - 0.5f; };  // [-1,1] → texel coordinate
    expect_lookup(bg, Vec3(0, 0, -1), pos(0), pos(0));
    expect_lookup(bg, Vec3(1, 0, 0), pos(0.5f), pos(0));
    expect_lookup(bg, Vec3(-1, 0, 0), pos(-0.5f), pos(0));
    expect_lookup(bg, Vec3(0, 1, 0), pos(0), pos(-0.5f));  // +y up: towards the top row
    expect_lookup(bg, Vec3(0, -1, 0), pos(0), pos(0.5f));
    expect_lookup(bg, normalize(Vec3(1, 0, -1)), pos(0.25f), pos(0));  // 45° from -z: a quarter out
    expect_lookup(bg, Vec3(0, 0, 1), 63.0f, pos(0));                   // the rim (clamped at the border)
}

TEST(EnvironmentLookup, DirectionsInvertTheUvMapsAndRotation) {
    const auto img = coordinate_image(64, 64);
    for (const glint::BackgroundKind kind :
         {glint::BackgroundKind::Equirectangular, glint::BackgroundKind::SphereMap, glint::BackgroundKind::AngularMap}) {
        const auto bg = glint::Background::environment(kind, img, 37.0f);
        for (Vec3 d : {Vec3(0.3f, -0.6f, 0.74f), Vec3(-0.5f, 0.3f, 0.8f), Vec3(0.2f, 0.9f, -0.5f),
                       Vec3(-0.7f, -0.1f, -0.4f)}) {
            d = normalize(d);
            const std::optional<Vec3> back = bg.direction_of(bg.uv_of(d));
            ASSERT_TRUE(back) << "direction " << d;
            EXPECT_NEAR(length(*back - d), 0.0f, 1e-4f) << "direction " << d << " kind " << int(kind);
        }
    }
    EXPECT_FALSE(glint::angular_map_direction(Vec2(0.02f, 0.02f))) << "a corner is off the disk";
    EXPECT_FALSE(glint::sphere_map_direction(Vec2(0.98f, 0.03f))) << "a corner is off the disk";
}

TEST(EnvironmentKind, ParsesNames) {
    EXPECT_EQ(glint::parse_environment_kind("equirect"), glint::BackgroundKind::Equirectangular);
    EXPECT_EQ(glint::parse_environment_kind("spheremap"), glint::BackgroundKind::SphereMap);
    EXPECT_EQ(glint::parse_environment_kind("angmap"), glint::BackgroundKind::AngularMap);
    EXPECT_EQ(glint::parse_environment_kind("angular"), glint::BackgroundKind::AngularMap);
    EXPECT_FALSE(glint::parse_environment_kind("cubemap"));
}

TEST(EnvironmentKind, ShapeMustFitANamedLayout) {
    EXPECT_FALSE(glint::environment_shape_problem(glint::BackgroundKind::Equirectangular, 64, 32));
    EXPECT_TRUE(glint::environment_shape_problem(glint::BackgroundKind::Equirectangular, 64, 64));
    EXPECT_FALSE(glint::environment_shape_problem(glint::BackgroundKind::AngularMap, 64, 64));
    EXPECT_TRUE(glint::environment_shape_problem(glint::BackgroundKind::AngularMap, 64, 32));
    EXPECT_TRUE(glint::environment_shape_problem(glint::BackgroundKind::SphereMap, 64, 32));
}

const std::filesystem::path kEnvDir = glint_test::kSharedDataDir / "env";

TEST(EnvironmentFiles, LoadGuessLayoutAndAgree) {
    const auto equirect = kEnvDir / "equirect/venice_sunset_1k.hdr";
    const auto ball = kEnvDir / "probe/venice_sunset_mirrorball_512.hdr";
    const auto angmap = kEnvDir / "probe/venice_sunset_angmap_512.hdr";
    if (!std::filesystem::exists(equirect) || !std::filesystem::exists(ball) || !std::filesystem::exists(angmap))
        GTEST_SKIP() << "no shared env maps";
    const glint::Background a = glint::load_environment(equirect);
    const glint::Background b = glint::load_environment(ball);
    const glint::Background c =
        glint::load_environment(angmap, {glint::BackgroundKind::AngularMap, 0.0f, 1.0f});
    EXPECT_EQ(a.kind(), glint::BackgroundKind::Equirectangular);
    EXPECT_EQ(b.kind(), glint::BackgroundKind::SphereMap);
    // The probes were re-projected from the lat-long map with the same conventions: away from
    // the ball's rim and from the busy horizon, both must show the same sky (nearest texels
    // of two resolutions differ by a few percent).
    for (Vec3 d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0.3f, -0.6f, 0.74f), Vec3(-0.5f, 0.3f, 0.8f),
                   Vec3(0.5f, 0.2f, 0.8f), Vec3(0.2f, 0.1f, -0.5f)}) {
        d = normalize(d);
        const glint::Color ca = a.evaluate(d), cb = b.evaluate(d), cc = c.evaluate(d);
        ASSERT_TRUE(ca.is_finite() && cb.is_finite() && cc.is_finite());
        EXPECT_NEAR(cb.luminance() / ca.luminance(), 1.0f, 0.15f) << "direction " << d;
        EXPECT_NEAR(cc.luminance() / ca.luminance(), 1.0f, 0.15f) << "angular map, direction " << d;
    }
    const glint::Color mean = glint::average_radiance(a);
    EXPECT_TRUE(mean.is_finite());
    EXPECT_GT(mean.luminance(), 0.0f);
}

TEST(EnvironmentFiles, MissingFileAndBadIntensityAreErrors) {
    EXPECT_THROW((void)glint::load_environment(kEnvDir / "no_such_map.hdr"), glint::ImageError);
    glint::EnvironmentOptions bad;
    bad.intensity = -1.0f;
    EXPECT_THROW((void)glint::load_environment(kEnvDir / "equirect/venice_sunset_1k.hdr", bad), std::invalid_argument);
}

}  // namespace
