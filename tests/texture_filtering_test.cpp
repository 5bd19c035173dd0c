// Texture filtering end to end: a checkerboard to the horizon rendered at 1 spp averages to
// its mean grey instead of aliasing, seen directly and in a mirror, in both integrators,
// procedural and image textures alike; and the pieces the footprint is made of (the shapes'
// ∂p/∂u, ∂p/∂v and curvature, the ray cone) against their closed forms.

#include "glint/geometry/disk.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_differentials.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/ray_cone.h"
#include "glint/materials/material_at_hit.h"
#include "glint/scene/camera.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace glint;

namespace {

/// A plane of checks 0.05/0.85 (mean 0.45), seen from 1 unit above it looking at the
/// horizon, or (mirror) looking at a vertical mirror 5 units ahead that shows the plane
/// behind the camera. The plane emits its texture and reflects nothing, so that a pixel's
/// value is the texture's there in both integrators, without noise.
std::string scene_text(const std::string& texture, bool mirror) {
    std::string text = R"(
[render]
width = 64
height = 48
spp = 1
max_depth = 3

[camera]
position = [0, 1, 0]
look_at = [0, 1, -10]
fov = 45

[world]
emission_lights = false
)" + texture + R"(
[[materials]]
name = "floor"
ambient = 0
diffuse = 0
emission = 1
emission_texture = "checks"

[[objects]]
type = "plane"
size = 4000
material = "floor"
)";
    if (mirror)
        text += R"(
[[materials]]
name = "mirror"
diffuse = 0
ambient = 0
reflectivity = 1

[[objects]]
type = "quad"
corner = [-100, 0.001, -5]
edge_u = [200, 0, 0]
edge_v = [0, 100, 0]
material = "mirror"
)";
    return text;
}

/// Checks of 0.02 units: 5 or more across a pixel of the band below, and far more along it.
std::string procedural_checks(int squares_across_the_plane = 200000) {
    return R"(
[[textures]]
name = "checks"
type = "checker"
even = 0.85
odd = 0.05
uv_scale = [)" + std::to_string(squares_across_the_plane) + ", " + std::to_string(squares_across_the_plane) + R"(]
)";
}

struct BandStatistics {
    double mean = 0.0, deviation = 0.0;
    int pixels = 0;
};

/// Mean and standard deviation of the red channel over rows 1 to 8 below the horizon (the
/// image's centre row), 7 to 40 units away, where a pixel is 0.1 to 0.7 units wide.
BandStatistics far_band(const std::string& text, const std::string& integrator,
                        const std::filesystem::path& base = glint_test::kScenesDir) {
    LoadedScene loaded = load_toml_scene_string(text, "checks.toml", base);
    loaded.settings.integrator = integrator;
    const RenderScene scene(std::move(loaded.scene));
    Film film(loaded.settings.width, loaded.settings.height);
    make_integrator(loaded.settings)->render(scene, loaded.settings, film);
    BandStatistics s;
    double sum = 0.0, squares = 0.0;
    for (uint32_t y = film.height() / 2 + 1; y <= film.height() / 2 + 8; ++y)
        for (uint32_t x = 0; x < film.width(); ++x) {
            const double v = film.at(x, y).r;
            sum += v;
            squares += v * v;
            ++s.pixels;
        }
    s.mean = sum / s.pixels;
    s.deviation = std::sqrt(std::max(0.0, squares / s.pixels - s.mean * s.mean));
    return s;
}

/// Point-sampled, the band's pixels are 0.05 or 0.85 at random (deviation about 0.4); a
/// filtered lookup makes them the mean, 0.45, with what remains of the squares' contrast.
void expect_grey(const BandStatistics& s, const std::string& what) {
    EXPECT_EQ(s.pixels, 8 * 64) << what;
    EXPECT_NEAR(s.mean, 0.45, 0.03) << what;
    EXPECT_LT(s.deviation, 0.05) << what;
}

}  // namespace

TEST(TextureFiltering, AFarCheckerboardAt1SppIsItsMeanGreyInBothIntegrators) {
    for (const char* integrator : {"whitted", "path"})
        expect_grey(far_band(scene_text(procedural_checks(), false), integrator), std::string(integrator) + ", direct");
}

TEST(TextureFiltering, AFarCheckerboardSeenInAMirrorIsFilteredForItsWholeDistance) {
    // The mirror is 5 units away and the band's checks 40 to 400 units behind it: a cone
    // that did not come through the reflection would look them up at a point.
    for (const char* integrator : {"whitted", "path"})
        expect_grey(far_band(scene_text(procedural_checks(), true), integrator), std::string(integrator) + ", mirror");
}

TEST(TextureFiltering, AFarImageCheckerboardIsMipMappedToItsMeanGrey) {
    const auto dir = glint_test::temp_dir();
    Image checks(64, 64, 3);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) checks.at(x, y, c) = ((x / 8 + y / 8) % 2 == 0) ? 0.85f : 0.05f;
    write_image(dir / "checks.exr", checks);
    const std::string texture = R"(
[[textures]]
name = "checks"
type = "image"
file = "checks.exr"
uv_scale = [25000, 25000]
)";
    for (const char* integrator : {"whitted", "path"}) {
        expect_grey(far_band(scene_text(texture, false), integrator, dir), std::string(integrator) + ", direct");
        expect_grey(far_band(scene_text(texture, true), integrator, dir), std::string(integrator) + ", mirror");
    }
}

TEST(TextureFiltering, NearChecksStaySharp) {
    // The bottom row sees squares of 4000/2000 = 2 units about 2.4 units away, many pixels
    // wide: filtering must not grey them.
    LoadedScene loaded =
        load_toml_scene_string(scene_text(procedural_checks(2000), false), "checks.toml", glint_test::kScenesDir);
    const RenderScene scene(std::move(loaded.scene));
    Film film(loaded.settings.width, loaded.settings.height);
    make_integrator(loaded.settings)->render(scene, loaded.settings, film);
    int crisp = 0;
    for (uint32_t x = 0; x < film.width(); ++x) {
        const float v = film.at(x, film.height() - 1).r;
        crisp += (std::abs(v - 0.85f) < 0.02f || std::abs(v - 0.05f) < 0.02f) ? 1 : 0;
    }
    EXPECT_GT(crisp, 48) << "of 64 pixels in the bottom row";
}

TEST(RayCone, GrowsAlongTheRayAndBouncesWiderOffACurvedSurface) {
    const RayCone camera{0.0f, 0.01f};
    const RayCone hit = camera.at(10.0f);
    EXPECT_FLOAT_EQ(hit.width, 0.1f);
    const RayCone flat = hit.bounced(0.0f);
    EXPECT_FLOAT_EQ(flat.at(5.0f).width, camera.at(15.0f).width);  // a plane mirror only folds the cone
    const RayCone ball = hit.bounced(1.0f / 0.5f);                  // a mirror ball of radius 0.5
    EXPECT_FLOAT_EQ(ball.spread, 0.01f + 2.0f * 2.0f * 0.1f);
}

TEST(RayCone, FootprintIsWidthOverUvScaleStretchedByObliquity) {
    SurfaceInteraction si;
    si.geometric_normal = Vec3(0, 1, 0);
    si.dpdu = Vec3(4, 0, 0);  // one unit of u spans 4 units, one of v 9: sqrt(36) = 6 per unit
    si.dpdv = Vec3(0, 0, 9);
    const RayCone cone{0.3f, 0.0f};
    EXPECT_FLOAT_EQ(cone.uv_footprint(si, Vec3(0, -1, 0)), 0.05f);
    EXPECT_NEAR(cone.uv_footprint(si, Vec3(0, -0.5f, std::sqrt(0.75f))), 0.1f, 1e-6f);  // 60° from the normal
    si.dpdu = Vec3();  // no uv map: a point lookup
    EXPECT_EQ(cone.uv_footprint(si, Vec3(0, -1, 0)), 0.0f);
}

TEST(RayCone, CameraRaysSpreadByOnePixelsAngleShared) {
    const Camera perspective = Camera::perspective(Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0), 90.0f);
    EXPECT_FLOAT_EQ(camera_ray_cone(perspective, 100, 1).spread, 2.0f / 100.0f);  // 2·tan 45° / 100
    EXPECT_FLOAT_EQ(camera_ray_cone(perspective, 100, 4).spread, 0.5f / 100.0f);
    EXPECT_FLOAT_EQ(camera_ray_cone(perspective, 100, 16).spread, 0.25f / 100.0f);  // at most 8 per axis
    const Camera ortho = Camera::orthographic(Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0), 3.0f);
    EXPECT_FLOAT_EQ(camera_ray_cone(ortho, 100, 1).width, 0.03f);
    EXPECT_EQ(camera_ray_cone(ortho, 100, 1).spread, 0.0f);
}

TEST(SurfaceDerivatives, TriangleMapFromUvToPositions) {
    // Positions = (2u + v, 3v, 1): the map the derivatives must recover exactly.
    auto p = [](Vec2 uv) { return Vec3(2 * uv.x + uv.y, 3 * uv.y, 1); };
    const Vec2 a(0.1f, 0.2f), b(0.9f, 0.3f), c(0.4f, 0.8f);
    const TriangleDerivatives d = triangle_derivatives(p(a), p(b), p(c), a, b, c);
    EXPECT_NEAR(length(d.dpdu - Vec3(2, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(length(d.dpdv - Vec3(1, 3, 0)), 0.0f, 1e-5f);
    const TriangleDerivatives none = triangle_derivatives(p(a), p(b), p(c), a, a, a);
    EXPECT_EQ(length(none.dpdu), 0.0f);
}

TEST(SurfaceDerivatives, VertexNormalsOfASphereGiveItsCurvature) {
    const float r = 2.5f;
    const Vec3 n0 = normalize(Vec3(1, 0.2f, 0)), n1 = normalize(Vec3(0.8f, 0.5f, 0.3f)), n2 = normalize(Vec3(0.9f, 0, 0.4f));
    EXPECT_NEAR(triangle_curvature(n0 * r, n1 * r, n2 * r, n0, n1, n2), 1.0f / r, 1e-5f);
    EXPECT_EQ(triangle_curvature(n0, n1, n2, n0, n0, n0), 0.0f);
}

TEST(SurfaceDerivatives, SphereAndDiskDerivativesMatchFiniteDifferencesOfTheirUvMaps) {
    // Step along ∂p/∂u (∂p/∂v) by ε and find the surface point there: its uv must have moved
    // by (ε, 0) ((0, ε)). The sphere's curvature is 1/r.
    const Sphere sphere(Vec3(0.5f, -1, 2), 1.5f);
    const Disk disk(Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0f);
    auto check = [](const Shape& shape, const Vec3& from, const Vec3& towards) {
        Ray ray(from, normalize(towards - from));
        Hit hit;
        ASSERT_TRUE(shape.intersect(ray, hit));
        SurfaceInteraction si;
        shape.interaction(ray, hit, si);
        constexpr float eps = 1e-3f;
        for (int axis = 0; axis < 2; ++axis) {
            const Vec3 moved = si.p + (axis == 0 ? si.dpdu : si.dpdv) * eps;
            Ray again(from, normalize(moved - from));
            Hit h2;
            ASSERT_TRUE(shape.intersect(again, h2));
            SurfaceInteraction s2;
            shape.interaction(again, h2, s2);
            const Vec2 expected = si.uv + (axis == 0 ? Vec2(eps, 0) : Vec2(0, eps));
            EXPECT_NEAR(s2.uv.x, expected.x, 5e-5f) << shape.type_name() << " axis " << axis;
            EXPECT_NEAR(s2.uv.y, expected.y, 5e-5f) << shape.type_name() << " axis " << axis;
        }
    };
    check(sphere, Vec3(3, 1, 6), Vec3(0.5f, -1, 2));
    check(disk, Vec3(0.3f, -0.2f, 5), Vec3(0.7f, 0.9f, 0));
    Ray ray(Vec3(3, 1, 6), normalize(Vec3(-2.5f, -2, -4)));
    Hit hit;
    ASSERT_TRUE(sphere.intersect(ray, hit));
    SurfaceInteraction si;
    sphere.interaction(ray, hit, si);
    EXPECT_FLOAT_EQ(si.curvature, 1.0f / 1.5f);
}

TEST(VertexColors, MultiplyTheBaseColourAndItsTexture) {
    Material m;
    m.diffuse = Color(0.5f);
    m.ambient = Color(0.5f);
    SurfaceInteraction si;
    si.vertex_color = Color(1.0f, 0.5f, 0.0f);
    const MaterialAtHit at = material_at_hit(m, si);
    EXPECT_EQ(at.diffuse, Color(0.5f, 0.25f, 0.0f));
    EXPECT_EQ(at.ambient, Color(0.5f, 0.25f, 0.0f));
    const CheckerTexture grey(Color(0.5f), Color(0.5f), 1.0f);
    m.texture = &grey;
    EXPECT_EQ(material_at_hit(m, si).diffuse, Color(0.25f, 0.125f, 0.0f));
}
