// The TOML scene format: every kind of mistake is reported at file:line:column with what
// was wrong and what was expected, and good files land in the Scene as written.

#include "glint/geometry/heightfield.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/default_scene.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_format/did_you_mean.h"
#include "glint/scene_format/source_excerpt.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"
#include "toml_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>

namespace glint {
namespace {

constexpr std::string_view kRed = "[[materials]]\nname = \"red\"\n";

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

// --- Mistakes -------------------------------------------------------------------------

TEST(TomlSceneErrors, MalformedToml) {
    expect_error("[camera\nposition = [1, 2, 3]\n", "test.toml:1:8:", {"invalid TOML"});
}

TEST(TomlSceneErrors, UnknownKeySuggestsTheClosest) {
    expect_error(std::string(kRed) + "difuse = 0.5\n", "test.toml:3:1:",
                 {"unknown key 'difuse'", "materials[0]", "did you mean 'diffuse'?",
                  "expected one of:", "\n 3 | difuse = 0.5\n   | ^"});
}

TEST(TomlSceneErrors, UnknownSection) {
    expect_error("[camra]\nfov = 30\n", "test.toml:1:2:", {"unknown key 'camra'", "did you mean 'camera'?"});
}

TEST(TomlSceneErrors, UnknownKeyWithoutCloseMatchListsTheKeys) {
    expect_error("[render]\nwidth = 64\ncolour_space = \"srgb\"\n", "test.toml:3:1:",
                 {"unknown key 'colour_space'",
                  "expected one of: adaptive, aovs, filter, filter_radius, glossy_samples, height, integrator, "
                  "light_samples, max_depth, mis, seed, spp, width"});
}

TEST(TomlSceneErrors, UnknownKeyInsideTransform) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n"
                     "transform = { scale = 2, translat = [0, 1, 0] }\n",
                 "test.toml:7:26:", {"unknown key 'translat'", "objects[0].transform", "did you mean 'translate'?"});
}

TEST(TomlSceneErrors, UnknownKeyInsideWaveList) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"heightfield\"\nresolution = [2, 2]\nmin = [0, 0]\n"
                     "max = [1, 1]\nmaterial = \"red\"\n"
                     "waves = [{ amplitude = 1, wavelength = 2, phaze = 3 }]\n",
                 "test.toml:9:43:", {"unknown key 'phaze'", "objects[0].waves[0]", "did you mean 'phase'?"});
}

TEST(TomlSceneErrors, UnknownKeyForThisShapeType) {
    // `positions` is a mesh key: a sphere must not swallow it silently.
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n"
                     "positions = [[0, 0, 0]]\n",
                 "test.toml:7:1:", {"unknown key 'positions'", "objects[0]"});
}

TEST(TomlSceneErrors, MisspeltRequiredKeyPointsAtTheMisspelling) {
    expect_error(std::string(kRed) + "[[objects]]\ntype = \"sphere\"\nraduis = 1\nmaterial = \"red\"\n",
                 "test.toml:5:1:", {"unknown key 'raduis'", "did you mean 'radius'?", "'radius' is required"});
}

TEST(TomlSceneErrors, MissingRequiredKey) {
    expect_error(std::string(kRed) + "[[objects]]\ntype = \"sphere\"\nmaterial = \"red\"\n",
                 "test.toml:3:1:", {"missing key 'radius'", "objects[0]", "expected a number"});
}

TEST(TomlSceneErrors, WrongType) {
    expect_error(std::string(kRed) + "[[objects]]\ntype = \"sphere\"\nradius = \"one\"\nmaterial = \"red\"\n",
                 "test.toml:5:10:", {"objects[0].radius is the string \"one\"", "expected a number"});
}

TEST(TomlSceneErrors, WrongArrayLength) {
    expect_error("[camera]\nposition = [1, 2]\nlook_at = [0, 0, 0]\n",
                 "test.toml:2:12:", {"camera.position is an array of 2", "expected [x, y, z]"});
}

TEST(TomlSceneErrors, NegativeRadius) {
    expect_error(std::string(kRed) + "[[objects]]\ntype = \"sphere\"\nradius = -1\nmaterial = \"red\"\n",
                 "test.toml:5:10:", {"objects[0].radius is -1", "expected a positive radius"});
}

TEST(TomlSceneErrors, NotANumber) {
    expect_error("[camera]\nposition = [1, nan, 3]\nlook_at = [0, 0, 0]\n",
                 "test.toml:2:16:", {"camera.position[1] is nan", "expected a finite number"});
}

TEST(TomlSceneErrors, Infinity) {
    expect_error("[world]\nambient_ior = inf\n", "test.toml:2:15:", {"world.ambient_ior is inf", "finite"});
}

TEST(TomlSceneErrors, DegenerateTriangle) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"triangle\"\nvertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2]]\n"
                     "material = \"red\"\n",
                 "test.toml:5:12:", {"objects[0].vertices is a degenerate triangle", "non-zero area"});
}

TEST(TomlSceneErrors, DegenerateMeshTriangle) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"mesh\"\npositions = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                     "indices = [[0, 1, 2], [0, 1, 1]]\nmaterial = \"red\"\n",
                 "test.toml:6:24:", {"triangle 1", "degenerate"});
}

TEST(TomlSceneErrors, IndexOutOfRange) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"mesh\"\npositions = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                     "indices = [0, 1, 3]\nmaterial = \"red\"\n",
                 "test.toml:6:18:", {"is 3", "a vertex index from 0 to 2"});
}

TEST(TomlSceneErrors, HeightfieldRowOfTheWrongLength) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"heightfield\"\nresolution = [3, 2]\nmin = [0, 0]\n"
                     "max = [1, 1]\nheights = [[0, 1, 2], [3, 4]]\nmaterial = \"red\"\n",
                 "test.toml:8:23:", {"objects[0].heights row is an array of 2", "nx = 3 heights"});
}

TEST(TomlSceneErrors, MissingTextureFile) {
    expect_error("[[textures]]\nname = \"t\"\ntype = \"image\"\nfile = \"assets/no_such_texture.png\"\n",
                 "test.toml:4:8:", {"textures[0].file", "no_such_texture.png", "expected an existing file"});
}

TEST(TomlSceneErrors, MissingMeshFile) {
    expect_error(std::string(kRed) + "[[objects]]\ntype = \"mesh\"\nfile = \"assets/no_such_mesh.ply\"\n",
                 "test.toml:5:8:", {"objects[0].file", "no_such_mesh.ply", "expected an existing file"});
}

TEST(TomlSceneErrors, MissingBackgroundFile) {
    expect_error("[background]\ntype = \"equirect\"\nfile = \"sky.hdr\"\n",
                 "test.toml:3:8:", {"background.file", "sky.hdr"});
}

TEST(TomlSceneErrors, UnknownMaterialSuggestsTheClosest) {
    expect_error(std::string(kRed) + "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"rde\"\n",
                 "test.toml:6:12:", {"objects[0].material is the string \"rde\"", "did you mean 'red'?"});
}

TEST(TomlSceneErrors, UnknownPerVertexMaterial) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"triangle\"\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                     "materials = [\"red\", \"red\", \"blue\"]\n",
                 "test.toml:6:28:", {"objects[0].materials[2]", "a material in [[materials]]"});
}

TEST(TomlSceneErrors, UnknownTextureSuggestsTheClosest) {
    expect_error(
        "[[textures]]\nname = \"checks\"\ntype = \"checker\"\n[[materials]]\nname = \"m\"\ntexture = \"chekcs\"\n",
        "test.toml:6:11:", {"materials[0].texture", "did you mean 'checks'?"});
}

TEST(TomlSceneErrors, UnknownChoiceSuggestsTheClosest) {
    expect_error(
        std::string(kRed) + "[[objects]]\ntype = \"shpere\"\nradius = 1\nmaterial = \"red\"\n",
        "test.toml:4:8:", {"objects[0].type is the string \"shpere\"", "one of \"sphere\"", "did you mean 'sphere'?"});
}

TEST(TomlSceneErrors, SamplesPerPixelMustBeSquare) {
    expect_error("[render]\nspp = 5\n", "test.toml:2:7:", {"render.spp is 5", "square number"});
}

TEST(TomlSceneErrors, DuplicateMaterialName) {
    expect_error(std::string(kRed) + std::string(kRed),
                 "test.toml:4:8:", {"materials[1].name", "not used by an earlier"});
}

TEST(TomlSceneErrors, HandoutAndSeminarDielectricTogether) {
    expect_error(std::string(kRed) + "refraction_index = 1.5\ntransparency = 0.5\n",
                 "test.toml:3:20:", {"refraction_index", "not both"});
}

TEST(TomlSceneErrors, ZeroIorCannotBeTransparent) {
    expect_error(std::string(kRed) + "ior = 0\ntransparency = 0.5\n", "test.toml:3:7:", {"ior = 0 means opaque"});
}

TEST(TomlSceneErrors, UnknownNamedShape) {
    expect_error(std::string(kRed) +
                     "[[shapes]]\nname = \"ball\"\ntype = \"sphere\"\nradius = 1\n"
                     "[[objects]]\nshape = \"bal\"\nmaterial = \"red\"\n",
                 "test.toml:8:9:", {"objects[0].shape", "did you mean 'ball'?"});
}

TEST(TomlSceneErrors, CameraLookingAtItself) {
    expect_error("[camera]\nposition = [1, 1, 1]\nlook_at = [1, 1, 1]\n", "test.toml:1:1:", {"camera", "position"});
}

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

TEST(TomlSceneErrors, LensKeys) {
    const std::string camera = "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\n";
    expect_error(camera + "aperture_radius = -1\n", "test.toml:4:19:", {"camera.aperture_radius is -1", "≥ 0"});
    expect_error(camera + "f_stop = 0\n", "test.toml:4:10:", {"positive f-number"});
    expect_error(camera + "focal_length = 50\n", "test.toml:4:16:", {"f_stop beside a focal length"});
    expect_error(camera + "aperture_blades = 1\n", "test.toml:4:19:", {"3 to 64 blades"});
    expect_error(camera + "focus_distance = 0\n", "test.toml:4:18:", {"positive distance"});
    expect_error(
        "[camera]\ntype = \"orthographic\"\nheight = 2\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nf_stop = 2\n",
        "test.toml:6:10:", {"focal_length beside f_stop"});
}

TEST(TomlSceneErrors, ZeroScale) {
    expect_error(std::string(kRed) +
                     "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n"
                     "transform = { scale = [1, 0, 1] }\n",
                 "test.toml:7:23:", {"objects[0].transform.scale", "non-zero scale"});
}

TEST(TomlSceneErrors, DatesAreRejected) {
    expect_error("[render]\nseed = 1979-05-27\n", "test.toml:2:8:", {"render.seed", "date"});
}

TEST(TomlSceneErrors, SectionOfTheWrongKind) {
    expect_error("[objects]\ntype = \"sphere\"\n", "test.toml:1:1:", {"objects is a table", "[[objects]]"});
}

TEST(TomlSceneErrors, DirectoryIsNotAScene) { EXPECT_THROW((void)load_toml_scene(glint_test::kScenesDir), SceneError); }

TEST(TomlSceneErrors, MissingSceneFileNamesIt) {
    try {
        (void)load_toml_scene(glint_test::kScenesDir / "no_such_scene.toml");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_scene.toml"), std::string::npos) << e.what();
    }
}

// --- Good files -----------------------------------------------------------------------

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

TEST(TomlSceneErrors, AlphaTextureOnAMeshWithoutUvs) {
    expect_error(R"(
[[textures]]
name = "half"
type = "image"
file = "../tests/data/left_opaque_right_clear.png"
[[materials]]
name = "leaf"
alpha_texture = "half"
[[objects]]
type = "mesh"
positions = [[0, 0, 0], [2, 0, 0], [2, 0, -1]]
indices = [[0, 1, 2]]
material = "leaf"
)",
                 "test.toml:13:12:", {"objects[0].material", "cuts out", "mesh does not have"});
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

constexpr std::string_view kGeometry = R"(
[[materials]]
name = "a"
[[materials]]
name = "b"
[[materials]]
name = "c"
[[shapes]]
name = "ball"
type = "sphere"
radius = 1
[[objects]]
shape = "ball"
material = "a"
transform = { scale = 2, translate = [1, 0, 0] }
[[objects]]
shape = "ball"
material = "b"
transform = [{ translate = [1, 0, 0] }, { scale = 2 }]
[[objects]]
type = "triangle"
vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
materials = ["a", "b", "c"]
[[objects]]
type = "mesh"
positions = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
indices = [0, 1, 2, 0, 2, 3]
uvs = [[0, 0], [1, 0], [1, 1], [0, 1]]
material = "c"
[[objects]]
type = "plane"
size = [4, 2]
material = "a"
transform = { rotate = [90, 0, 0] }
[[objects]]
type = "box"
min = [-1, -1, -1]
max = [1, 1, 1]
material = "b"
[[objects]]
type = "heightfield"
resolution = [3, 2]
min = [0, 0]
max = [2, 1]
height = 1
heights = [[0, 1, 2], [3, 4, 5]]
waves = [{ amplitude = 0.5, wavelength = 4 }]
material = "c"
)";

TEST(TomlScene, ObjectsAndSharedShapes) {
    const LoadedScene s = load(kGeometry);
    const auto& objects = s.scene.objects();
    ASSERT_EQ(objects.size(), 7u);
    EXPECT_EQ(objects[0].shape, objects[1].shape) << "objects placing one named shape share it (instancing)";
    EXPECT_EQ(objects[0].material, 0u);
    EXPECT_EQ(objects[1].material, 1u);
    EXPECT_EQ(objects[4].shape->type_name(), "quad");
    EXPECT_EQ(objects[5].shape->type_name(), "box");
    const auto* mesh = dynamic_cast<const TriangleMesh*>(objects[3].shape.get());
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(mesh->triangle_count(), 2u);
    EXPECT_EQ(mesh->data().uvs.size(), 4u);
    EXPECT_EQ(objects[3].material, 2u);
}

TEST(TomlScene, TransformTableIsScaleRotateTranslateAndListIsInOrder) {
    const LoadedScene s = load(kGeometry);
    // Table: scale 2 then translate → (1,0,0) ↦ (3,0,0). List: translate then scale → (4,0,0).
    EXPECT_EQ(s.scene.objects()[0].world_from_object.point(Vec3(1, 0, 0)), Vec3(3, 0, 0));
    EXPECT_EQ(s.scene.objects()[1].world_from_object.point(Vec3(1, 0, 0)), Vec3(4, 0, 0));
    // Euler x = 90°: the plane's +y normal turns to +z.
    const Vec3 n = s.scene.objects()[4].world_from_object.vector(Vec3(0, 1, 0));
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    EXPECT_NEAR(n.y, 0.0f, 1e-6f);
}

TEST(TomlScene, TrianglePerVertexMaterials) {
    const LoadedScene s = load(kGeometry);
    const auto* tri = dynamic_cast<const TriangleMesh*>(s.scene.objects()[2].shape.get());
    ASSERT_NE(tri, nullptr);
    EXPECT_EQ(tri->data().vertex_materials, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(TomlScene, HeightfieldAddsGridHeightsAndWaves) {
    const LoadedScene s = load(kGeometry);
    const auto* hf = dynamic_cast<const Heightfield*>(s.scene.objects()[6].shape.get());
    ASSERT_NE(hf, nullptr);
    // Vertex (i=1, j=1) sits at x = 1: base 1 + grid 4 + 0.5·sin(2π·1/4).
    EXPECT_NEAR(hf->height(1, 1), 1.0f + 4.0f + 0.5f, 1e-5f);
    EXPECT_NEAR(hf->height(0, 0), 1.0f, 1e-5f);
}

TEST(TomlScene, SpheresFileMatchesTheBuiltInScene) {
    for (const bool refraction : {false, true}) {
        const LoadedScene file =
            load_toml_scene(glint_test::kScenesDir / (refraction ? "spheres_refraction.toml" : "spheres.toml"));
        const Scene built_in = make_spheres_scene(refraction);
        ASSERT_EQ(file.scene.objects().size(), built_in.objects().size());
        ASSERT_EQ(file.scene.materials().size(), built_in.materials().size());
        for (std::size_t i = 0; i < built_in.materials().size(); ++i) {
            const Material &a = file.scene.material(uint32_t(i)), &b = built_in.material(uint32_t(i));
            EXPECT_NEAR(a.diffuse.r, b.diffuse.r, 1e-6f) << "material " << i;
            EXPECT_NEAR(a.diffuse.g, b.diffuse.g, 1e-6f) << "material " << i;
            EXPECT_NEAR(a.diffuse.b, b.diffuse.b, 1e-6f) << "material " << i;
            EXPECT_EQ(a.ambient == a.diffuse, b.ambient == b.diffuse);
            EXPECT_NEAR(a.reflectivity.r, b.reflectivity.r, 1e-6f);
            EXPECT_EQ(a.transparency, b.transparency);
            EXPECT_EQ(a.ior, b.ior);
            EXPECT_EQ(a.specular, b.specular);
            EXPECT_EQ(a.shininess, b.shininess);
        }
        for (std::size_t i = 0; i < built_in.objects().size(); ++i) {
            EXPECT_EQ(file.scene.objects()[i].material, built_in.objects()[i].material) << "object " << i;
            EXPECT_EQ(file.scene.objects()[i].world_from_object, built_in.objects()[i].world_from_object)
                << "object " << i;
        }
        EXPECT_EQ(file.scene.lights().size(), built_in.lights().size());
        EXPECT_EQ(file.scene.ambient_light, built_in.ambient_light);
        EXPECT_EQ(file.scene.dielectric_shadows, built_in.dielectric_shadows);
        EXPECT_EQ(file.scene.background.color(), built_in.background.color());
        EXPECT_EQ(file.scene.camera.eye(), built_in.camera.eye());
    }
}

TEST(SourceExcerpt, CaretUnderTheColumn) {
    EXPECT_EQ(source_excerpt("a = 1\n\tb = nan\n", 2, 6), "\n 2 | \tb = nan\n   | \t    ^");
    EXPECT_EQ(source_excerpt("a = 1\r\n", 1, 1), "\n 1 | a = 1\n   | ^");
    EXPECT_EQ(source_excerpt("a = 1", 3, 1), "");
}

// --- Suggestions ----------------------------------------------------------------------

TEST(DidYouMean, EditDistance) {
    EXPECT_EQ(edit_distance("radius", "radius"), 0u);
    EXPECT_EQ(edit_distance("raduis", "radius"), 1u);  // adjacent swap
    EXPECT_EQ(edit_distance("radis", "radius"), 1u);
    EXPECT_EQ(edit_distance("Diffuse", "diffuse"), 0u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
}

TEST(DidYouMean, OnlyCloseCandidates) {
    const std::vector<std::string> keys{"width", "height", "spp"};
    EXPECT_EQ(closest_match("heigth", keys), "height");
    EXPECT_EQ(closest_match("sp", keys), "spp");
    EXPECT_FALSE(closest_match("colour_space", keys).has_value());
}

}  // namespace
}  // namespace glint
