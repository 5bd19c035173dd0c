// The TOML scene format's mistakes: every kind is reported at file:line:column with what was
// wrong and what was expected (good files: toml_scene_test.cpp).

#include "glint/scene_format/did_you_mean.h"
#include "glint/scene_format/source_excerpt.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"
#include "toml_text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace glint {
namespace {

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
