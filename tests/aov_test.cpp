// AOVs (image/aov.h): first-hit layers of known scenes against their materials and geometry,
// the sampling layers against their formulas, and how they are written.

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/image/aov_film.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/lights/light.h"
#include "glint/math/constants.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace glint;

namespace {

constexpr uint32_t kSide = 32;
const std::vector<Aov> kAll{Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Spp, Aov::Variance};

/// Channel `name` of `image` at (x, y).
float channel(const Image& image, const std::string& name, uint32_t x, uint32_t y) {
    for (int c = 0; c < image.channels; ++c)
        if (image.channel_names[std::size_t(c)] == name) return image.at(int(x), int(y), c);
    ADD_FAILURE() << "no channel " << name;
    return 0.0f;
}

Vec3 channel3(const Image& image, const std::string& layer, const char* xyz, uint32_t x, uint32_t y) {
    return {channel(image, layer + "." + xyz[0], x, y), channel(image, layer + "." + xyz[1], x, y),
            channel(image, layer + "." + xyz[2], x, y)};
}

/// The image with every AOV of `scene` rendered by `integrator`.
Image render_aovs(Scene scene, const std::string& integrator, uint32_t samples_per_axis, uint32_t threads = 0) {
    const RenderScene prepared(std::move(scene));
    RenderSettings settings;
    settings.width = settings.height = kSide;
    settings.samples_per_axis = samples_per_axis;
    settings.integrator = integrator;
    settings.threads = threads;
    settings.aovs = kAll;
    Film film(kSide, kSide);
    AovFilm aovs(kSide, kSide, kAll);
    (void)make_integrator(settings)->render(prepared, settings, film, {}, nullptr, nullptr, &aovs);
    return aovs.append_to(film.to_image());
}

/// A Lambert sphere of radius 1 at (0, 0, −4) seen from the origin, filling part of the view,
/// on a black background.
Scene sphere_scene(const Color& kd) {
    Scene scene;
    Material m;
    m.diffuse = kd;
    // Whitted's ambient term makes every visible point of the sphere at least 1 bright.
    m.ambient = Color(1.0f);
    scene.ambient_light = Color(1.0f);
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, -4), 1.0f), scene.add_material(m));
    scene.add_light(std::make_unique<PointLight>(Vec3(2, 3, 0), Color(10.0f), Falloff::InverseSquare));
    scene.camera = Camera::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40.0f);
    return scene;
}

}  // namespace

TEST(Aovs, FirstHitLayersOfASphereMatchItsMaterialAndGeometry) {
    const Color kd(0.7f, 0.5f, 0.3f);
    for (const std::string integrator : {"whitted", "path"}) {
        // One sample per pixel: each pixel's layers are one hit's values, exactly.
        const Image image = render_aovs(sphere_scene(kd), integrator, 1);
        int hits = 0, misses = 0;
        for (uint32_t y = 0; y < kSide; ++y)
            for (uint32_t x = 0; x < kSide; ++x) {
                const float z = channel(image, "Z", x, y);
                const Vec3 albedo = channel3(image, "albedo", "RGB", x, y);
                if (std::isinf(z)) {
                    ++misses;
                    EXPECT_EQ(albedo, Vec3(0.0f));
                    EXPECT_EQ(channel3(image, "N", "XYZ", x, y), Vec3(0.0f));
                    continue;
                }
                ++hits;
                EXPECT_EQ(albedo, Vec3(kd.r, kd.g, kd.b)) << integrator;
                const Vec3 p = channel3(image, "P", "XYZ", x, y);
                EXPECT_NEAR(length(p - Vec3(0, 0, -4)), 1.0f, 1e-5f);  // on the sphere
                EXPECT_NEAR(z, length(p), 1e-5f);                      // along the ray from the eye
                const Vec3 n = channel3(image, "N", "XYZ", x, y);
                EXPECT_NEAR(length(n - (p - Vec3(0, 0, -4))), 0.0f, 1e-5f) << integrator;
                EXPECT_EQ(channel(image, "spp", x, y), 1.0f);
                EXPECT_EQ(channel(image, "variance.R", x, y), 0.0f);  // one sample: no spread
            }
        EXPECT_GT(hits, 100);
        EXPECT_GT(misses, 100);
    }
}

TEST(Aovs, DepthOfAPlaneSeenOrthographicallyIsItsDistance) {
    // An orthographic camera's rays are parallel: every one meets the plane z = −3 after 3.
    Scene scene;
    Material m;
    m.diffuse = Color(0.25f);
    scene.add_object(std::make_shared<Quad>(Vec3(-5, -5, -3), Vec3(10, 0, 0), Vec3(0, 10, 0)), scene.add_material(m));
    scene.camera = Camera::orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 2.0f);
    const Image image = render_aovs(std::move(scene), "whitted", 3);
    for (uint32_t y = 0; y < kSide; y += 5)
        for (uint32_t x = 0; x < kSide; x += 5) {
            EXPECT_NEAR(channel(image, "Z", x, y), 3.0f, 1e-6f);
            EXPECT_NEAR(channel(image, "P.Z", x, y), -3.0f, 1e-6f);
            EXPECT_NEAR(channel(image, "N.Z", x, y), 1.0f, 1e-6f);  // towards the camera
            EXPECT_NEAR(channel(image, "albedo.G", x, y), 0.25f, 1e-6f);
            EXPECT_EQ(channel(image, "spp", x, y), 9.0f);
        }
}

TEST(Aovs, VarianceIsTheVarianceOfThePixelMean) {
    AovFilm film(1, 1, {Aov::Variance, Aov::Spp});
    for (const float v : {1.0f, 2.0f, 3.0f, 4.0f}) film.add_sample(0, 0, FirstHit{}, Color(v, 2.0f * v, 5.0f));
    Image beauty(1, 1, 3);
    beauty.channel_names = {"R", "G", "B"};
    const Image image = film.append_to(beauty);
    // s² of 1, 2, 3, 4 is 5/3; the mean of four samples has a quarter of it.
    EXPECT_NEAR(channel(image, "variance.R", 0, 0), 5.0f / 12.0f, 1e-6f);
    EXPECT_NEAR(channel(image, "variance.G", 0, 0), 4.0f * 5.0f / 12.0f, 1e-6f);
    EXPECT_EQ(channel(image, "variance.B", 0, 0), 0.0f);
    EXPECT_EQ(channel(image, "spp", 0, 0), 4.0f);
}

TEST(Aovs, VarianceIsHighOnlyWhereThePixelSeesAnEdge) {
    const Image image = render_aovs(sphere_scene(Color(0.8f)), "whitted", 4);
    // The centre sees only the sphere (smooth shading: a tiny spread); a corner sees only
    // the black background (none); a pixel on the silhouette sees both (radiance ≥ 1 and 0).
    const float centre = channel(image, "variance.R", kSide / 2, kSide / 2);
    EXPECT_EQ(channel(image, "variance.R", 0, 0), 0.0f);
    float edge = 0.0f;
    for (uint32_t x = 0; x < kSide; ++x) edge = std::max(edge, channel(image, "variance.R", x, kSide / 2));
    EXPECT_GT(edge, 0.01f);
    EXPECT_LT(centre, 1e-3f);
}

TEST(Aovs, OneAndTwoThreadsWriteTheSameLayers) {
    const Image one = render_aovs(sphere_scene(Color(0.6f)), "path", 2, 1);
    const Image two = render_aovs(sphere_scene(Color(0.6f)), "path", 2, 2);
    EXPECT_EQ(one.pixels, two.pixels);
}

TEST(Aovs, AnExrKeepsTheNamedChannels) {
    const Image image = render_aovs(sphere_scene(Color(0.6f)), "whitted", 1);
    const std::filesystem::path dir = glint_test::temp_dir();
    write_image(dir / "aovs.exr", image);
    const Image back = read_image(dir / "aovs.exr");
    ASSERT_EQ(back.channels, 3 + 14);
    // The file orders channels its own way: find each by name.
    ASSERT_EQ(back.channel_names.size(), 17u);
    for (const std::string& name : image.channel_names)
        for (uint32_t y = 0; y < kSide; y += 7)
            for (uint32_t x = 0; x < kSide; x += 7) {
                const float a = channel(image, name, x, y), b = channel(back, name, x, y);
                EXPECT_TRUE(a == b || (std::isinf(a) && std::isinf(b))) << name;
            }
    // A PNG takes the colour only.
    write_image(dir / "aovs.png", image);
    EXPECT_EQ(read_image(dir / "aovs.png").channels, 3);
    std::filesystem::remove_all(dir);
}
