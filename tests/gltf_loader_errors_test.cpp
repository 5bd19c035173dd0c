// Broken glTF input, generated from good files into a temp dir: each gives an error or a
// warning that names the file and the problem, the CLI exits non-zero only when nothing can
// be rendered, and nothing crashes (CI runs this under AddressSanitizer).

#include "cli_runner.h"
#include "gltf_test_files.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/assets/mesh_loader.h"
#include "glint/diagnostics.h"

#include "source_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The SceneError message of loading `path` ("" if it loads).
std::string load_error(const fs::path& path) {
    try {
        (void)glint::load_gltf_scene(path);
    } catch (const glint::SceneError& e) {
        return e.what();
    }
    return "";
}

bool has_warning(const std::vector<std::string>& warnings, const std::string& a, const std::string& b) {
    for (const auto& w : warnings)
        if (w.find(a) != std::string::npos && w.find(b) != std::string::npos) return true;
    return false;
}

glint_test::CliResult run_cli(const std::string& args, const fs::path& dir) {
    return glint_test::run_cli(GLINT_CLI, args, dir);
}

TEST(GltfErrors, TruncatedGlbNamesTheFile) {
    const fs::path dir = glint_test::temp_dir();
    const std::string glb = glint_test::make_glb(glint_test::quad_json(""), glint_test::quad_buffer());
    for (std::size_t keep : {std::size_t(0), std::size_t(10), std::size_t(30), glb.size() - 20}) {
        const fs::path path = dir / ("cut" + std::to_string(keep) + ".glb");
        glint_test::write_file(path, glb.substr(0, keep));
        const std::string error = load_error(path);
        EXPECT_NE(error.find(path.filename().string()), std::string::npos) << "cut at " << keep << ": " << error;
    }
    const fs::path good = dir / "good.glb";
    glint_test::write_file(good, glb);
    EXPECT_EQ(load_error(good), "");
}

TEST(GltfErrors, TruncatedSampleGlbFailsCleanlyInTheCli) {
    const fs::path duck = glint_test::kSharedDataDir / "gltf/Duck/glTF-Binary/Duck.glb";
    if (!fs::exists(duck)) GTEST_SKIP() << "no shared data at " << duck;
    const fs::path dir = glint_test::temp_dir();
    const std::string bytes = glint_test::read_file(duck);
    glint_test::write_file(dir / "Duck.glb", bytes.substr(0, bytes.size() / 2));
    const glint_test::CliResult r =
        run_cli("render " + (dir / "Duck.glb").string() + " -q -o " + (dir / "x.png").string(), dir);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("Duck.glb"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(GltfErrors, MissingBinNamesTheBuffer) {
    const fs::path dir = glint_test::temp_dir();
    const fs::path path = glint_test::write_gltf(dir, "quad", glint_test::quad_json("quad.bin"));
    fs::remove(dir / "quad.bin");
    const std::string error = load_error(path);
    EXPECT_NE(error.find("quad.gltf"), std::string::npos) << error;
    EXPECT_NE(error.find("quad.bin"), std::string::npos) << error;
    EXPECT_NE(error.find("missing"), std::string::npos) << error;
    const glint_test::CliResult r = run_cli("render " + path.string() + " -q -o " + (dir / "x.png").string(), dir);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("quad.bin"), std::string::npos) << r.err;
}

TEST(GltfErrors, ShortBinIsTruncated) {
    const fs::path dir = glint_test::temp_dir();
    const fs::path path = glint_test::write_gltf(dir, "quad", glint_test::quad_json("quad.bin"));
    glint_test::write_file(dir / "quad.bin", glint_test::quad_buffer().substr(0, 40));
    EXPECT_NE(load_error(path).find("truncated"), std::string::npos) << load_error(path);
}

TEST(GltfErrors, MissingTextureWarnsAndRenders) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    j["images"] = json::array({{{"uri", "gone.png"}}});
    j["textures"] = json::array({{{"source", 0}}});
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const fs::path path = glint_test::write_gltf(dir, "quad", j);
    const glint::GltfScene s = glint::load_gltf_scene(path);
    EXPECT_TRUE(has_warning(s.loaded.warnings, "quad.gltf", "gone.png"));
    EXPECT_EQ(s.loaded.scene.materials()[0].texture, nullptr);
    const glint_test::CliResult r =
        run_cli("render " + path.string() + " --width 8 --height 6 -o " + (dir / "x.png").string(), dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("gone.png"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir / "x.png"));
}

TEST(GltfErrors, UnsupportedExtensionsGiveOneWarningEach) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    j["extensionsUsed"] = {"EXT_glint_unknown", "KHR_materials_sheen"};
    j["extensionsRequired"] = {"EXT_glint_unknown"};
    j["materials"][0]["extensions"]["KHR_materials_sheen"] = {{"sheenColorFactor", {1, 1, 1}}};
    const glint::GltfScene s = glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", j));
    int unknown = 0, sheen = 0;
    for (const auto& w : s.loaded.warnings) {
        unknown += w.find("EXT_glint_unknown") != std::string::npos;
        sheen += w.find("KHR_materials_sheen") != std::string::npos;
        EXPECT_NE(w.find("quad.gltf"), std::string::npos) << w;
    }
    EXPECT_EQ(unknown, 1);
    EXPECT_EQ(sheen, 1);
    EXPECT_EQ(s.report.ignored.size(), 2u);
    EXPECT_EQ(s.loaded.scene.objects().size(), 1u) << "the render goes on";
}

TEST(GltfErrors, InfoListsWhatWasMappedAndIgnored) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    j["extensionsUsed"] = {"EXT_glint_unknown"};
    const fs::path path = glint_test::write_gltf(dir, "quad", j);
    const glint_test::CliResult r = run_cli("info " + path.string(), dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* expected : {"triangles:   2 unique, 2 instanced", "materials:   1", "cameras:     0 in the file",
                                 "bounds:", "memory:", "mapped:", "automatic camera", "ignored:", "EXT_glint_unknown"})
        EXPECT_NE(r.out.find(expected), std::string::npos) << "missing '" << expected << "' in:\n" << r.out;
}

TEST(GltfErrors, SkinnedMeshIsDrawnInBindPoseWithOneWarning) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("skin.bin");
    // JOINTS_0 (4 × u8 VEC4, all joint 0) and WEIGHTS_0 (4 × float VEC4, weight 1 on joint 0).
    std::string bin = glint_test::quad_buffer() + std::string(16, '\0');
    for (int v = 0; v < 4; ++v) {
        const float w[4] = {1, 0, 0, 0};
        bin.append(reinterpret_cast<const char*>(w), 16);
    }
    j["buffers"][0]["byteLength"] = bin.size();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 16}});
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 88}, {"byteLength", 64}});
    j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5121}, {"count", 4}, {"type", "VEC4"}});
    j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}});
    j["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = 2;
    j["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = 3;
    j["nodes"][0]["skin"] = 0;
    j["nodes"].push_back({{"name", "bone"}});
    j["scenes"][0]["nodes"].push_back(1);
    j["skins"] = json::array({{{"joints", {1}}}});
    glint_test::write_file(dir / "skin.bin", bin);
    glint_test::write_file(dir / "skin.gltf", j.dump());
    const glint::GltfScene s = glint::load_gltf_scene(dir / "skin.gltf");
    EXPECT_EQ(s.report.triangles, 2u);
    // assimp 5.2.5 crashes on this valid file (a skin without inverseBindMatrices) when it
    // reads the skin itself: the loader hands it the geometry only.
    int skin_lines = 0;
    for (const auto& w : s.loaded.warnings) skin_lines += w.find("ignored skin") != std::string::npos;
    EXPECT_EQ(skin_lines, 1);
}

TEST(GltfErrors, NanPositionsAreDroppedWithAWarning) {
    const fs::path dir = glint_test::temp_dir();
    const fs::path path = glint_test::write_gltf(dir, "quad", glint_test::quad_json("quad.bin"));
    std::string bin = glint_test::quad_buffer();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bin.data() + 36, &nan, 4);  // vertex 3, x: only the second triangle uses it
    glint_test::write_file(dir / "quad.bin", bin);
    glint::GltfScene s = glint::load_gltf_scene(path);
    EXPECT_EQ(s.report.triangles, 1u);
    EXPECT_TRUE(has_warning(s.loaded.warnings, "quad.gltf", "non-finite"));
}

TEST(GltfErrors, BadJsonAndWrongVersionAreErrors) {
    const fs::path dir = glint_test::temp_dir();
    glint_test::write_file(dir / "bad.gltf", "{ \"asset\": { \"version\": \"2.0\" ");
    EXPECT_NE(load_error(dir / "bad.gltf").find("bad.gltf"), std::string::npos);
    glint_test::write_file(dir / "old.gltf", R"({"asset": {"version": "1.0"}})");
    EXPECT_NE(load_error(dir / "old.gltf").find("expected 2"), std::string::npos) << load_error(dir / "old.gltf");
    json j = glint_test::quad_json("quad.bin");
    j["nodes"][0]["mesh"] = "zero";  // wrong type
    EXPECT_NE(load_error(glint_test::write_gltf(dir, "typed", j)).find("typed.gltf"), std::string::npos);
}

TEST(GltfErrors, HostileHierarchyDoesNotCrash) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    // node 1 and 2 form a cycle, node 0 lists itself and a child that does not exist.
    j["nodes"][0]["children"] = {0, 1, 99};
    j["nodes"].push_back({{"mesh", 0}, {"children", {2}}, {"translation", {1, 0, 0}}});
    j["nodes"].push_back({{"mesh", 0}, {"children", {1}}, {"translation", {0, 1, 0}}});
    j["scenes"][0]["nodes"] = {0, 7};
    const glint::GltfScene s = glint::load_gltf_scene(glint_test::write_gltf(dir, "cycle", j));
    EXPECT_EQ(s.report.objects, 3u);
}

TEST(GltfErrors, AccessorsOutsideTheirBufferAreErrors) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    j["accessors"][0]["count"] = 1000;  // 12 kB of positions in a 48-byte view
    std::string error = load_error(glint_test::write_gltf(dir, "long", j));
    EXPECT_NE(error.find("long.gltf"), std::string::npos) << error;
    EXPECT_NE(error.find("accessor 0"), std::string::npos) << error;
    j = glint_test::quad_json("quad.bin");
    j["bufferViews"][1]["byteLength"] = 4000;
    error = load_error(glint_test::write_gltf(dir, "view", j));
    EXPECT_NE(error.find("outside its buffer"), std::string::npos) << error;
    j = glint_test::quad_json("quad.bin");
    j["meshes"][0]["primitives"][0]["indices"] = 9;
    error = load_error(glint_test::write_gltf(dir, "dangling", j));
    EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
    j = glint_test::quad_json("quad.bin");
    j["nodes"][0]["mesh"] = 3;
    error = load_error(glint_test::write_gltf(dir, "nomesh", j));
    EXPECT_NE(error.find("mesh 3"), std::string::npos) << error;
}

// The geometry check counts the bad index values and assimp drops their triangles: the
// file renders without them, through both entry points, and one warning says so.
TEST(GltfErrors, OutOfRangeIndexValuesDropTheirTriangles) {
    const fs::path dir = glint_test::temp_dir();
    const fs::path path = glint_test::write_gltf(dir, "quad", glint_test::quad_json("quad.bin"));
    std::string bin = glint_test::quad_buffer();
    const uint32_t bad = 77;
    std::memcpy(bin.data() + 48 + 5 * 4, &bad, 4);  // second triangle (0, 2, 77) uses vertex 77 of 4
    glint_test::write_file(dir / "quad.bin", bin);
    const std::string warning =
        "quad.gltf: mesh 0 primitive 0: 1 out-of-range vertex index(es) (expected below 4); their triangles are "
        "dropped";

    const glint::GltfScene s = glint::load_gltf_scene(path);
    EXPECT_EQ(s.report.triangles, 1u);
    EXPECT_EQ(std::count_if(s.loaded.warnings.begin(), s.loaded.warnings.end(),
                            [&](const std::string& w) { return w.find("out-of-range") != std::string::npos; }),
              1);
    EXPECT_TRUE(has_warning(s.loaded.warnings, warning, dir.string())) << testing::PrintToString(s.loaded.warnings);

    glint::Scene scene;
    glint::MeshCache cache;
    const auto result = glint::import_mesh_file(scene, path, glint::Transform(), std::nullopt, cache);
    EXPECT_EQ(result.triangles, 1u);
    EXPECT_TRUE(has_warning(result.warnings, warning, dir.string())) << testing::PrintToString(result.warnings);
    const auto& mesh = dynamic_cast<const glint::TriangleMesh&>(*scene.objects().at(0).shape);
    EXPECT_EQ(mesh.data().indices, (std::vector<uint32_t>{0, 1, 2})) << "the good triangle is kept as it was";
}

/// A quad file with a second node, `node`, that places the quad where rays cannot reach it:
/// the node is skipped with `warning` (after the file name) whichever way the file comes
/// in, and the first node still draws.
void expect_node_skipped(const json& node, const std::string& warning) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    j["nodes"].push_back(node);
    j["scenes"][0]["nodes"].push_back(1);
    const fs::path path = glint_test::write_gltf(dir, "node", j);
    const std::string expected = "node.gltf: ignored node with " + warning;

    const glint::GltfScene s = glint::load_gltf_scene(path);
    EXPECT_EQ(s.report.objects, 1u);
    EXPECT_TRUE(has_warning(s.loaded.warnings, expected, dir.string())) << testing::PrintToString(s.loaded.warnings);

    glint::Scene scene;
    glint::MeshCache cache;
    const auto result = glint::import_mesh_file(scene, path, glint::Transform(), std::nullopt, cache);
    EXPECT_EQ(result.objects, 1u);
    EXPECT_TRUE(has_warning(result.warnings, expected, dir.string())) << testing::PrintToString(result.warnings);
}

// A node scaled to zero has no inverse for ray queries.
TEST(GltfErrors, SingularNodesAreSkippedWithAWarning) {
    expect_node_skipped({{"name", "flattened"}, {"mesh", 0}, {"scale", {1, 0, 1}}},
                        "a singular transform (scale 0) (on 'flattened')");
}

// A node matrix whose last row is not 0, 0, 0, 1 (glTF requires an affine one) would map
// rays projectively, which Glint's object transforms never do. Column-major: element 3 is
// row 3, column 0.
TEST(GltfErrors, ProjectiveNodesAreSkippedWithAWarning) {
    expect_node_skipped(
        {{"name", "projective"}, {"mesh", 0}, {"matrix", {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}},
        "a projective transform (last row not 0, 0, 0, 1) (on 'projective')");
}

TEST(GltfErrors, NoGeometryIsAnError) {
    const fs::path dir = glint_test::temp_dir();
    json j = glint_test::quad_json("quad.bin");
    j["nodes"][0].erase("mesh");
    const std::string error = load_error(glint_test::write_gltf(dir, "empty", j));
    EXPECT_NE(error.find("empty.gltf"), std::string::npos) << error;
}

TEST(GltfErrors, ImportIntoASceneSharesTheChecks) {
    const fs::path dir = glint_test::temp_dir();
    const std::string glb = glint_test::make_glb(glint_test::quad_json(""), glint_test::quad_buffer());
    glint_test::write_file(dir / "cut.glb", glb.substr(0, glb.size() - 8));
    glint::Scene scene;
    glint::MeshCache cache;
    EXPECT_THROW(glint::import_mesh_file(scene, dir / "cut.glb", glint::Transform(), std::nullopt, cache),
                 glint::SceneError);
    glint_test::write_file(dir / "good.glb", glb);
    const auto result = glint::import_mesh_file(scene, dir / "good.glb", glint::Transform(), std::nullopt, cache);
    EXPECT_EQ(result.triangles, 2u);
    EXPECT_EQ(scene.material(scene.objects()[0].material).name, "white");
}

}  // namespace
