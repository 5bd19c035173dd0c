// The TOML scene format: good files land in the Scene as written (mistakes:
// toml_scene_errors_test.cpp; objects and shapes: toml_shapes_test.cpp).

#include "glint/geometry/sphere.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"
#include "toml_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace glint {
namespace {

// --- Text ------------------------------------------------------------------------------

TEST(TomlSceneText, NonAsciiCharactersWhereWhitespaceMayStandAreText) {
    // Debian's toml++ took a non-ASCII character there for an unreachable case (undefined
    // behaviour: toml_scene_loader.cpp says more); the sanitizer build stops at it.
    const LoadedScene line_ending_backslash = load(
        "[[materials]]\nname = \"\"\"\\\n\u00a7 red\"\"\"\n"
        "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"\u00a7 red\"\n");
    EXPECT_EQ(line_ending_backslash.scene.materials().front().name, "\u00a7 red");
    const LoadedScene comment_in_array = load(std::string(kRed) +
                                              "diffuse = [0.1, # a 5\u00d75 grid\n  0.2, 0.3]\n"
                                              "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n");
    EXPECT_EQ(comment_in_array.scene.materials().front().name, "red");
}

// --- Good files -----------------------------------------------------------------------

TEST(TomlScene, CameraLensFromApertureOrFStop) {
    const std::string camera = "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 1]\nfov = 40\n";
    // Without lens keys: a pinhole, focused (should a lens be given) on look_at.
    const ThinLens pinhole = load(camera).scene.camera.lens();
    EXPECT_TRUE(pinhole.is_pinhole());
    EXPECT_FLOAT_EQ(pinhole.focus_distance, 4.0f);
    const ThinLens radius = load(camera + "aperture_radius = 0.05\n").scene.camera.lens();
    EXPECT_FLOAT_EQ(radius.aperture_radius, 0.05f);
    EXPECT_FLOAT_EQ(radius.focus_distance, 4.0f);
    // A 50 mm lens at f/2: an aperture 25 mm across, in metres.
    const ThinLens f_stop =
        load(camera + "f_stop = 2\nfocal_length = 50\nfocus_distance = 3\naperture_blades = 5\n").scene.camera.lens();
    EXPECT_FLOAT_EQ(f_stop.aperture_radius, 0.0125f);
    EXPECT_FLOAT_EQ(f_stop.focus_distance, 3.0f);
    EXPECT_EQ(f_stop.blades, 5u);
    // Without a focal length, the one that gives a 40° fov on 35 mm film (24 mm high).
    const ThinLens from_fov = load(camera + "f_stop = 4\n").scene.camera.lens();
    EXPECT_FLOAT_EQ(from_fov.aperture_radius, 0.001f * (12.0f / std::tan(radians(20.0f))) / 8.0f);
}

TEST(TomlScene, AovsInOrderEachOnce) {
    const LoadedScene loaded = load("[render]\naovs = [\"depth\", \"albedo\", \"depth\", \"variance\"]\n");
    EXPECT_EQ(loaded.settings.aovs, (std::vector<Aov>{Aov::Depth, Aov::Albedo, Aov::Variance}));
    expect_error(
        "[render]\naovs = [\"albedo\", \"Z\"]\n", "test.toml:2:19:",
        {"render.aovs[1] is the string \"Z\"", "expected one of albedo, normal, depth, position, spp, variance"});
    expect_error("[render]\naovs = \"albedo\"\n", "test.toml:2:8:", {"render.aovs", "array"});
}

TEST(TomlScene, AdaptiveSampling) {
    const LoadedScene loaded = load("[render]\nadaptive = { min_spp = 2, max_spp = 256, threshold = 0.05 }\n");
    ASSERT_TRUE(loaded.settings.adaptive);
    EXPECT_EQ(loaded.settings.samples_per_axis, 16u);
    EXPECT_EQ(loaded.settings.adaptive->min_spp, 2u);
    EXPECT_FLOAT_EQ(loaded.settings.adaptive->threshold, 0.05f);
    const LoadedScene defaults = load("[render]\nadaptive = {}\n");
    EXPECT_EQ(defaults.settings.samples_per_axis, 8u);
    EXPECT_EQ(defaults.settings.adaptive->min_spp, 4u);
    EXPECT_FALSE(load("[render]\nspp = 4\n").settings.adaptive);
    expect_error("[render]\nadaptive = { max_spp = 36 }\n", "test.toml:2:24:", {"a power of 4"});
    expect_error("[render]\nadaptive = { max_spp = 16, min_spp = 32 }\n", "test.toml:2:38:", {"from 1 to 16"});
    expect_error("[render]\nadaptive = { threshold = 0 }\n", "test.toml:2:26:", {"positive relative error"});
    expect_error("[render]\nspp = 16\nadaptive = {}\n", "test.toml:2:7:", {"spp or adaptive.max_spp, not both"});
}

TEST(TomlScene, EmptyFileIsTheDefaults) {
    const LoadedScene s = load("");
    EXPECT_EQ(s.settings.width, RenderSettings{}.width);
    EXPECT_EQ(s.settings.max_depth, 5u);
    EXPECT_TRUE(s.scene.objects().empty());
}

TEST(TomlScene, WarnsAboutAnUnlitScene) {
    EXPECT_EQ(load("").warnings.size(), 1u);  // no objects
    const LoadedScene unlit =
        load(std::string(kRed) + "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n");
    ASSERT_EQ(unlit.warnings.size(), 1u);
    EXPECT_NE(unlit.warnings[0].find("no [[lights]]"), std::string::npos) << unlit.warnings[0];
    EXPECT_TRUE(load_toml_scene(glint_test::kScenesDir / "cornell.toml").warnings.empty());
}

TEST(TomlScene, RenderSettings) {
    const LoadedScene s =
        load("[render]\nwidth = 320\nheight = 200\nspp = 9\nmax_depth = 3\nseed = 42\nfilter = \"tent\"\n");
    EXPECT_EQ(s.settings.width, 320u);
    EXPECT_EQ(s.settings.height, 200u);
    EXPECT_EQ(s.settings.samples_per_axis, 3u);
    EXPECT_EQ(s.settings.max_depth, 3u);
    EXPECT_EQ(s.settings.seed, 42u);
    EXPECT_EQ(s.settings.filter, PixelFilter::Tent);
}

TEST(TomlScene, PerspectiveCamera) {
    const LoadedScene s = load("[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nup = [0, 1, 0]\nfov = 30\n");
    EXPECT_EQ(s.scene.camera.projection(), Projection::Perspective);
    EXPECT_EQ(s.scene.camera.eye(), Vec3(0, 0, 5));
    EXPECT_NEAR(s.scene.camera.forward().z, -1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(s.scene.camera.vertical_fov(), 30.0f);
}

TEST(TomlScene, OrthographicCamera) {
    const LoadedScene s = load(
        "[camera]\ntype = \"orthographic\"\nposition = [0, 5, 0]\nlook_at = [0, 0, 0]\n"
        "up = [0, 0, -1]\nheight = 4\n");
    EXPECT_EQ(s.scene.camera.projection(), Projection::Orthographic);
    EXPECT_FLOAT_EQ(s.scene.camera.view_height(), 4.0f);
}

TEST(TomlScene, WorldAndBackground) {
    const LoadedScene s = load(
        "[world]\nambient_light = [0.1, 0.2, 0.3]\nambient_ior = 1.33\n"
        "dielectric_shadows = \"opaque\"\n[background]\ncolor = 0.5\n");
    EXPECT_EQ(s.scene.ambient_light, Color(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(s.scene.ambient_ior, 1.33f);
    EXPECT_EQ(s.scene.dielectric_shadows, DielectricShadows::Opaque);
    EXPECT_EQ(s.scene.background.kind(), BackgroundKind::Constant);
    EXPECT_EQ(s.scene.background.color(), Color(0.5f));
}

TEST(TomlScene, EnvironmentLightingIsOffUnlessAsked) {
    EXPECT_FALSE(load("[background]\ncolor = 0.5\n").scene.environment_lighting);
    EXPECT_TRUE(load("[world]\nenvironment_lighting = true\n[background]\ncolor = 0.5\n").scene.environment_lighting);
}

TEST(TomlScene, SphereMapBackgroundResolvesAgainstTheSceneFolder) {
    const LoadedScene s = load(
        "[background]\ntype = \"spheremap\"\nfile = \"assets/venice_sunset_mirrorball_512.hdr\"\n"
        "rotation = 90\nintensity = 2\n");
    EXPECT_EQ(s.scene.background.kind(), BackgroundKind::SphereMap);
    ASSERT_NE(s.scene.background.image(), nullptr);
    EXPECT_EQ(s.scene.background.image()->width, 512);
}

TEST(TomlScene, EveryMaterialField) {
    const LoadedScene s = load(R"(
[[textures]]
name = "checks"
type = "checker"
even = 1
odd = 0
scale = 4
[[materials]]
name = "m"
ambient = [0.1, 0.2, 0.3]
diffuse = 0.5
texture = "checks"
specular = 0.25
shininess = 12
reflectivity = [0.3, 0.4, 0.5]
fresnel_mirror = true
transparency = 0.75
ior = 1.4
emission = 2
emission_texture = "checks"
alpha_texture = "checks"
alpha_cutoff = 0.25
roughness = 0.5
)");
    const Material& m = s.scene.material(0);
    EXPECT_EQ(m.name, "m");
    EXPECT_EQ(m.ambient, Color(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(m.diffuse, Color(0.5f));
    ASSERT_NE(m.texture, nullptr);
    EXPECT_EQ(m.texture->type_name(), "checker");
    EXPECT_EQ(m.specular, Color(0.25f));
    EXPECT_FLOAT_EQ(m.shininess, 12.0f);
    EXPECT_EQ(m.reflectivity, Color(0.3f, 0.4f, 0.5f));
    EXPECT_TRUE(m.fresnel_mirror);
    EXPECT_FLOAT_EQ(m.transparency, 0.75f);
    EXPECT_FLOAT_EQ(m.ior, 1.4f);
    EXPECT_EQ(m.emission, Color(2.0f));
    EXPECT_EQ(m.emission_texture, m.texture);
    EXPECT_EQ(m.alpha_texture, m.texture);
    EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.25f);
    EXPECT_FLOAT_EQ(m.roughness, 0.5f);
}

// The cut-out is behaviour, not a stored field: rays pass where the texture is clear.
TEST(TomlScene, AlphaTextureCutsOutAMeshForCameraAndShadowRays) {
    LoadedScene s = load(R"(
[[textures]]
name = "half"
type = "image"
file = "../tests/data/left_opaque_right_clear.png"
wrap = "clamp"
[[materials]]
name = "leaf"
alpha_texture = "half"
[[objects]]
type = "mesh"
positions = [[0, 0, 0], [2, 0, 0], [2, 0, -1], [0, 0, -1]]
uvs = [[0, 0], [1, 0], [1, 1], [0, 1]]
indices = [[0, 1, 2], [0, 2, 3]]
material = "leaf"
)");
    const RenderScene scene(std::move(s.scene));
    const Vec3 down(0.0f, -1.0f, 0.0f);
    for (const float x : {0.2f, 0.6f, 1.4f, 1.8f}) {
        const bool opaque = x < 1.0f;  // u = x / 2: the left texel is opaque, the right one clear
        Ray ray(Vec3(x, 1.0f, -0.5f), down);
        Hit hit;
        EXPECT_EQ(scene.intersect(ray, hit), opaque) << "x = " << x;
        EXPECT_EQ(scene.occluded(Ray(Vec3(x, 1.0f, -0.5f), down)), opaque) << "x = " << x;
    }
}

// Every shape cuts out, not only meshes: a sphere whose near side is clear is hit on its far
// side, a quad like the mesh above.
TEST(TomlScene, AlphaTextureCutsOutAnalyticShapes) {
    LoadedScene s = load(R"(
[[textures]]
name = "half"
type = "image"
file = "../tests/data/left_opaque_right_clear.png"
wrap = "clamp"
[[materials]]
name = "leaf"
alpha_texture = "half"
[[objects]]
type = "sphere"
radius = 1
material = "leaf"
[[objects]]
type = "quad"
corner = [0, 0, 3]
edge_u = [2, 0, 0]
edge_v = [0, 0, -1]
material = "leaf"
)");
    const RenderScene scene(std::move(s.scene));
    // The sphere's u is its azimuth from +x / 2π: z > 0 (u < 0.5) opaque, z < 0 clear.
    const float far_side = 5.0f + std::sqrt(1.0f - 0.09f);
    Ray from_back(Vec3(0.3f, 0.0f, -5.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f);
    Hit hit;
    ASSERT_TRUE(scene.intersect(from_back, hit));
    EXPECT_NEAR(from_back.tmax, far_side, 1e-4f) << "the clear near side is stepped over";
    Ray from_front(Vec3(0.3f, 0.0f, 2.5f), Vec3(0.0f, 0.0f, -1.0f), 0.0f, 10.0f);
    ASSERT_TRUE(scene.intersect(from_front, hit));
    EXPECT_NEAR(from_front.tmax, 2.5f - std::sqrt(1.0f - 0.09f), 1e-4f);
    // A ray grazing only the clear half passes; shadow rays agree.
    EXPECT_FALSE(scene.occluded(Ray(Vec3(0.3f, 0.0f, -5.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f, 4.5f)));
    EXPECT_TRUE(scene.occluded(Ray(Vec3(0.3f, 0.0f, -5.0f), Vec3(0.0f, 0.0f, 1.0f), 0.0f, 10.0f)));
    // The quad at z in [2, 3]: its u runs along x over [0, 2].
    for (const float x : {0.2f, 0.6f, 1.4f, 1.8f}) {
        const bool opaque = x < 1.0f;
        Ray ray(Vec3(x, 1.0f, 2.5f), Vec3(0.0f, -1.0f, 0.0f));
        EXPECT_EQ(scene.intersect(ray, hit), opaque) << "x = " << x;
        EXPECT_EQ(scene.occluded(Ray(Vec3(x, 1.0f, 2.5f), Vec3(0.0f, -1.0f, 0.0f))), opaque) << "x = " << x;
    }
}

TEST(TomlScene, HandoutRefractionIndex) {
    const LoadedScene s = load(
        "[[materials]]\nname = \"water\"\nrefraction_index = 1.33\n"
        "[[materials]]\nname = \"wall\"\nrefraction_index = 0\n"
        "[[materials]]\nname = \"opaque\"\nior = 0\n");
    EXPECT_FLOAT_EQ(s.scene.material(0).transparency, 1.0f);
    EXPECT_FLOAT_EQ(s.scene.material(0).ior, 1.33f);
    EXPECT_FALSE(s.scene.material(1).is_dielectric());
    EXPECT_FALSE(s.scene.material(2).is_dielectric());
}

TEST(TomlScene, ImageTextureWithUvScale) {
    const LoadedScene s = load(
        "[[textures]]\nname = \"t\"\ntype = \"image\"\n"
        "file = \"assets/kenney_prototype_orange_checker_1024.png\"\nwrap = \"repeat\"\n"
        "uv_scale = [4, 4]\n[[materials]]\nname = \"m\"\ntexture = \"t\"\n");
    ASSERT_NE(s.scene.material(0).texture, nullptr);
    // Four repeats: uv 0.1 and 0.35 land on the same texel of the image.
    const Texture& t = *s.scene.material(0).texture;
    const Color a = t.evaluate({0.1f, 0.1f}, {}), b = t.evaluate({0.35f, 0.35f}, {});
    EXPECT_NEAR(a.r, b.r, 1e-5f);
}

TEST(TomlScene, Lights) {
    const LoadedScene s = load(R"(
[[lights]]
type = "point"
position = [1, 2, 3]
intensity = [4, 5, 6]
falloff = "inverse_square"
[[lights]]
type = "directional"
direction = [0, -2, 0]
intensity = 0.5
[[lights]]
type = "spot"
position = [0, 5, 0]
direction = [0, -1, 0]
inner_angle = 10
outer_angle = 20
)");
    ASSERT_EQ(s.scene.lights().size(), 3u);
    const auto* point = dynamic_cast<const PointLight*>(s.scene.lights()[0].get());
    ASSERT_NE(point, nullptr);
    EXPECT_EQ(point->position(), Vec3(1, 2, 3));
    EXPECT_EQ(point->intensity(), Color(4, 5, 6));
    EXPECT_EQ(point->falloff(), Falloff::InverseSquare);
    const auto* sun = dynamic_cast<const DirectionalLight*>(s.scene.lights()[1].get());
    ASSERT_NE(sun, nullptr);
    EXPECT_EQ(sun->direction(), Vec3(0, -1, 0));
    EXPECT_EQ(sun->irradiance(), Color(0.5f));
    const LightSample inside = s.scene.lights()[2]->sample(Vec3(0, 0, 0), {});
    const LightSample outside = s.scene.lights()[2]->sample(Vec3(5, 0, 0), {});  // 45° off the axis
    EXPECT_EQ(inside.radiance, Color(kPi));  // physical: π × the π-scaled intensity
    EXPECT_TRUE(outside.radiance.is_black());
}

}  // namespace
}  // namespace glint
