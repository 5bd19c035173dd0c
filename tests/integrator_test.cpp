// Radiance of simple scenes against closed-form answers, shadows, recursion, determinism.

#include "glint/geometry/box.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/math/constants.h"
#include "glint/scene/default_scene.h"
#include "glint/scene/scene.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace glint;

namespace {

/// Radiance along one ray with the Whitted integrator.
Color radiance(const RenderScene& scene, const Ray& ray, uint32_t max_depth = 5) {
    Sampler sampler(0, 1);
    sampler.start_pixel_sample(0, 0);
    TraceContext context{sampler};
    return WhittedIntegrator(max_depth).Li(scene, ray, context);
}

void expect_color_near(const Color& a, const Color& b, float eps) {
    EXPECT_NEAR(a.r, b.r, eps);
    EXPECT_NEAR(a.g, b.g, eps);
    EXPECT_NEAR(a.b, b.b, eps);
}

Material lambert_material(const Color& kd, const Color& ka = Color(0.0f)) {
    Material m;
    m.diffuse = kd;
    m.ambient = ka;
    return m;
}

}  // namespace

TEST(WhittedRadiance, LambertSphereUnderInverseSquarePointLight) {
    Scene scene;
    const Color kd(0.7f, 0.5f, 0.3f);
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 0, 0), 1.0f), scene.add_material(lambert_material(kd)));
    const Vec3 light_pos(3, 4, 5);
    const Color intensity(20.0f, 10.0f, 5.0f);
    scene.add_light(std::make_unique<PointLight>(light_pos, intensity, Falloff::InverseSquare));
    const RenderScene prepared(std::move(scene));
    for (const Vec3& target : {Vec3(0, 0, 1), normalize(Vec3(1, 1, 1)), normalize(Vec3(0.2f, 0.9f, 0.3f))}) {
        const Vec3 eye = target * 6.0f;
        const Color L = radiance(prepared, Ray(eye, normalize(target - eye)));
        const Vec3 to_light = light_pos - target;
        const float d2 = dot(to_light, to_light);
        const float cos_theta = dot(target, normalize(to_light));
        ASSERT_GT(cos_theta, 0.0f);
        // L = kd · I · cos θ / d²
        expect_color_near(L, kd * intensity * (cos_theta / d2), 1e-3f);
    }
}

TEST(WhittedRadiance, AssignmentLightsDoNotFallOff) {
    Scene scene;
    scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20)),
                     scene.add_material(lambert_material(Color(0.5f))));
    scene.add_light(std::make_unique<PointLight>(Vec3(0, 100, 0), Color(0.8f), Falloff::None));
    const RenderScene prepared(std::move(scene));
    // Straight below the light: cos θ = 1, no 1/d²: L = kd · I.
    expect_color_near(radiance(prepared, Ray({0, 1, 0.0f}, {0, -1, 0})), Color(0.4f), 1e-5f);
}

TEST(WhittedRadiance, PlaneUnderDirectionalLightRendersTheFormulaEverywhere) {
    Scene scene;
    const Color kd(0.6f), ka(0.5f);
    scene.ambient_light = Color(0.1f);
    scene.add_object(std::make_shared<Quad>(Vec3(-100, 0, 100), Vec3(200, 0, 0), Vec3(0, 0, -200)),
                     scene.add_material(lambert_material(kd, ka)));
    const Vec3 dir = normalize(Vec3(1, -2, 0.5f));  // direction the light travels
    const Color e(2.0f);
    scene.add_light(std::make_unique<DirectionalLight>(dir, e));
    scene.camera = Camera::perspective({0, 5, 5}, {0, 0, 0}, {0, 1, 0}, 30.0f);
    const RenderScene prepared(std::move(scene));
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    settings.samples_per_axis = 2;
    Film film(settings.width, settings.height);
    const RenderStats stats = WhittedIntegrator().render(prepared, settings, film);
    // ka·La + kd·E·cos θ with cos θ = -dir.y.
    const Color expected = ka * prepared.ambient_light() + kd * e * (-dir.y);
    for (uint32_t y = 0; y < settings.height; ++y)
        for (uint32_t x = 0; x < settings.width; ++x) expect_color_near(film.at(x, y), expected, 1e-5f);
    // Every sample: one camera ray and one shadow ray.
    EXPECT_EQ(stats.rays, 2u * settings.width * settings.height * 4u);
}

TEST(WhittedRadiance, ShadowedPointGetsOnlyAmbient) {
    Scene scene;
    const Color kd(0.8f), ka(0.3f);
    scene.ambient_light = Color(0.2f);
    const uint32_t m = scene.add_material(lambert_material(kd, ka));
    scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20)), m);
    scene.add_object(std::make_shared<Sphere>(Vec3(0, 2, 0), 0.5f), m);  // blocker above the origin
    scene.add_light(std::make_unique<PointLight>(Vec3(0, 5, 0), Color(1.0f), Falloff::None));
    const RenderScene prepared(std::move(scene));
    const Color shadowed = radiance(prepared, Ray({0.05f, 1, 0.05f}, {0, -1, 0}));
    expect_color_near(shadowed, ka * prepared.ambient_light(), 1e-6f);
    const Color lit = radiance(prepared, Ray({5, 1, 5}, {0, -1, 0}));
    EXPECT_GT(lit.r, shadowed.r + 0.1f);
}

TEST(WhittedRadiance, LightBehindTheSurfaceContributesNothing) {
    Scene scene;
    scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20)),
                     scene.add_material(lambert_material(Color(1.0f))));
    scene.add_light(std::make_unique<PointLight>(Vec3(0, -5, 0), Color(1.0f), Falloff::None));
    const RenderScene prepared(std::move(scene));
    expect_color_near(radiance(prepared, Ray({0, 1, 0}, {0, -1, 0})), Color(0.0f), 0.0f);
}

TEST(WhittedRadiance, BlinnPhongHighlightAtTheMirrorDirection) {
    Scene scene;
    Material m = lambert_material(Color(0.0f));
    m.specular = Color(0.5f);
    m.shininess = 20.0f;
    scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20)), scene.add_material(m));
    scene.add_light(std::make_unique<PointLight>(Vec3(0, 10, 0), Color(1.0f), Falloff::None));
    const RenderScene prepared(std::move(scene));
    // Viewer and light both straight above: H = N, highlight = ks·E·cos θ = 0.5.
    expect_color_near(radiance(prepared, Ray({0, 1, 0}, {0, -1, 0})), Color(0.5f), 1e-5f);
    // Off the mirror direction it falls as (N·H)^s.
    const Vec3 eye(3, 3, 0), p(0, 0, 0);
    const Vec3 h = normalize(normalize(eye - p) + Vec3(0, 1, 0));
    const float expected = 0.5f * std::pow(h.y, 20.0f);
    EXPECT_NEAR(radiance(prepared, Ray(eye, normalize(p - eye))).r, expected, 1e-5f);
}

TEST(WhittedRadiance, MirrorReflectsTheBackgroundWeightedByReflectivity) {
    Scene scene;
    scene.background = Background::constant(Color(0.2f, 0.4f, 0.8f));
    Material mirror = lambert_material(Color(0.0f));
    mirror.reflectivity = Color(0.9f, 0.5f, 0.25f);
    scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20)),
                     scene.add_material(mirror));
    const RenderScene prepared(std::move(scene));
    expect_color_near(radiance(prepared, Ray({0, 1, 0}, normalize(Vec3(1, -1, 0)))),
                      Color(0.18f, 0.2f, 0.2f), 1e-6f);
    // Depth 0: no recursion at all, the mirror is black.
    expect_color_near(radiance(prepared, Ray({0, 1, 0}, {0, -1, 0}), 0), Color(0.0f), 0.0f);
}

TEST(WhittedRadiance, GlassSlabHeadOnFollowsFresnel) {
    // A slab of index 1.5 seen head-on in front of a uniform background B, depth 2:
    // front face F·B + (1-F)·[back face: F·(cut) + (1-F)·B] = B·(F + (1-F)²), F = 0.04.
    Scene scene;
    const Color b(1.0f, 0.5f, 0.25f);
    scene.background = Background::constant(b);
    Material glass = lambert_material(Color(0.0f));
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    scene.add_object(std::make_shared<Box>(Vec3(-5, -5, -0.5f), Vec3(5, 5, 0.5f)), scene.add_material(glass));
    const RenderScene prepared(std::move(scene));
    const float f = 0.04f;
    const Ray head_on({0, 0, 5}, {0, 0, -1});
    expect_color_near(radiance(prepared, head_on, 2), b * (f + (1 - f) * (1 - f)), 1e-5f);
    expect_color_near(radiance(prepared, head_on, 1), b * f, 1e-6f);
}

TEST(WhittedRadiance, GlassShowsItsBlinnPhongHighlight) {
    // A clear dielectric (t = 1) takes no diffuse light, but its highlight is the surface's:
    // head-on under a light straight above, the glass slab adds ks·E to the Fresnel result.
    Scene scene;
    Material glass = lambert_material(Color(0.8f));
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    glass.specular = Color(0.5f);
    glass.shininess = 50.0f;
    scene.add_object(std::make_shared<Box>(Vec3(-5, -0.5f, -5), Vec3(5, 0.5f, 5)), scene.add_material(glass));
    scene.add_light(std::make_unique<PointLight>(Vec3(0, 10, 0), Color(1.0f), Falloff::None));
    const RenderScene prepared(std::move(scene));
    // Depth 0: no reflection or refraction, only what the surface itself adds.
    expect_color_near(radiance(prepared, Ray({0, 5, 0}, {0, -1, 0}), 0), Color(0.5f), 1e-5f);
}

TEST(WhittedRadiance, TotalInternalReflectionKeepsLightInside) {
    // A ray inside glass meeting the surface beyond the critical angle is reflected whole,
    // so none of the (white) background outside reaches it.
    Scene scene;
    Material glass = lambert_material(Color(0.0f));
    glass.transparency = 1.0f;
    glass.ior = 1.5f;
    scene.add_object(std::make_shared<Box>(Vec3(-10, -1, -10), Vec3(10, 0, 10)), scene.add_material(glass));
    scene.background = Background::constant(Color(1.0f));
    const RenderScene prepared(std::move(scene));
    // Start inside the glass, 60° from the top face's normal (critical angle 41.8°).
    const Vec3 d = normalize(Vec3(std::sin(radians(60.0f)), std::cos(radians(60.0f)), 0));
    IorStack inside = IorStack(1.0f).entered(0, 1.5f);
    Sampler sampler(0, 1);
    sampler.start_pixel_sample(0, 0);
    TraceContext ctx{sampler};
    const WhittedIntegrator integrator(1);
    // With depth 1 the TIR reflection is traced but cut: black, never the background.
    const Color c = integrator.trace(prepared, Ray({0, -0.5f, 0}, d), 0, inside, ctx);
    expect_color_near(c, Color(0.0f), 1e-6f);
    // At 20° (below critical) most light leaves: we see mostly the white background.
    const Vec3 d2 = normalize(Vec3(std::sin(radians(20.0f)), std::cos(radians(20.0f)), 0));
    const Color c2 = integrator.trace(prepared, Ray({0, -0.5f, 0}, d2), 0, inside, ctx);
    EXPECT_GT(c2.r, 0.9f);
}

TEST(WhittedRadiance, PerVertexMaterialsBlendWithBarycentrics) {
    Scene scene;
    const uint32_t red = scene.add_material(lambert_material(Color(1, 0, 0)));
    const uint32_t green = scene.add_material(lambert_material(Color(0, 1, 0)));
    const uint32_t blue = scene.add_material(lambert_material(Color(0, 0, 1)));
    MeshData d;
    d.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    d.indices = {0, 1, 2};
    d.vertex_materials = {red, green, blue};
    scene.add_object(std::make_shared<TriangleMesh>(d), red);
    scene.add_light(std::make_unique<DirectionalLight>(Vec3(0, -1, 0), Color(1.0f)));
    const RenderScene prepared(std::move(scene));
    // Barycentric weights (0.5, 0.25, 0.25) at p = 0.25·v1 + 0.25·v2.
    expect_color_near(radiance(prepared, Ray({0.25f, 1, -0.25f}, {0, -1, 0})), Color(0.5f, 0.25f, 0.25f), 1e-5f);
}

TEST(WhittedRadiance, SpotLightConeCutsOff) {
    const SpotLight spot({0, 10, 0}, {0, -1, 0}, Color(1.0f), radians(10.0f), radians(20.0f), Falloff::None);
    EXPECT_FLOAT_EQ(spot.sample({0, 0, 0}, {}).radiance.r / kPi, 1.0f);  // on the axis
    const float inside = 10.0f * std::tan(radians(5.0f)), outside = 10.0f * std::tan(radians(25.0f));
    EXPECT_FLOAT_EQ(spot.sample({inside, 0, 0}, {}).radiance.r / kPi, 1.0f);
    EXPECT_FLOAT_EQ(spot.sample({outside, 0, 0}, {}).radiance.r, 0.0f);
    const float between = spot.sample({10.0f * std::tan(radians(15.0f)), 0, 0}, {}).radiance.r / kPi;
    EXPECT_GT(between, 0.0f);
    EXPECT_LT(between, 1.0f);
}

TEST(Render, IdenticalForAnyThreadCount) {
    Scene scene = make_spheres_scene();
    const RenderScene prepared(std::move(scene));
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.samples_per_axis = 2;
    settings.seed = 42;
    Film one(64, 48), two(64, 48);
    settings.threads = 1;
    WhittedIntegrator().render(prepared, settings, one);
    settings.threads = 2;
    WhittedIntegrator().render(prepared, settings, two);
    for (uint32_t y = 0; y < 48; ++y)
        for (uint32_t x = 0; x < 64; ++x) ASSERT_EQ(one.at(x, y), two.at(x, y)) << x << "," << y;
    // A different seed moves the jittered samples: the image must change somewhere.
    settings.seed = 43;
    Film other(64, 48);
    WhittedIntegrator().render(prepared, settings, other);
    bool differs = false;
    for (uint32_t y = 0; y < 48 && !differs; ++y)
        for (uint32_t x = 0; x < 64 && !differs; ++x) differs = !(one.at(x, y) == other.at(x, y));
    EXPECT_TRUE(differs);
}
