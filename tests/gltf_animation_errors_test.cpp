// Broken glTF animations: with a shutter each is a SceneError naming the file and the JSON
// path of the mistake (nothing crashes; CI runs this under AddressSanitizer); without one
// the animations are ignored, as before, and the file loads.

#include "gltf_animation_files.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/diagnostics.h"

#include <gtest/gtest.h>

#include <functional>

namespace fs = std::filesystem;
using glint_test::AnimatedQuad;

namespace {

/// The SceneError message of loading `path` with the shutter [0, 1] ("" if it loads).
std::string shutter_error(const fs::path& path) {
    try {
        glint::GltfOptions options;
        options.shutter = glint::Shutter{0.0f, 1.0f};
        (void)glint::load_gltf_scene(path, options);
    } catch (const glint::SceneError& e) {
        return e.what();
    }
    return "";
}

struct Broken {
    const char* name;
    std::function<void(AnimatedQuad&)> make;
    /// What the message says after the file name.
    std::string expected;
};

void PrintTo(const Broken& broken, std::ostream* os) { *os << broken.name; }

class GltfAnimationErrors : public testing::TestWithParam<Broken> {};

TEST_P(GltfAnimationErrors, NameTheFileAndTheJsonPath) {
    AnimatedQuad quad;
    GetParam().make(quad);
    const fs::path path = quad.write(glint_test::temp_dir(), GetParam().name);
    const std::string error = shutter_error(path);
    EXPECT_EQ(error.rfind(path.string() + ": ", 0), 0u) << error;
    EXPECT_NE(error.find(GetParam().expected), std::string::npos) << error;
    EXPECT_NO_THROW((void)glint::load_gltf_scene(path)) << "without a shutter, animations are ignored";
}

const Broken kBroken[] = {
    {"times_not_increasing",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f, 1.0f}, {0, 0, 0, 1, 0, 0, 2, 0, 0});
     },
     "animations[0].samplers[0].input: key time 2 (1.000000) does not come after key time 1 (1.000000)"},
    {"times_decreasing",
     [](AnimatedQuad& q) {
         q.channel(0, "scale", {0.0f, 1.0f}, {1, 1, 1, 2, 2, 2});
         q.channel(0, "translation", {1.0f, 0.5f}, {0, 0, 0, 1, 0, 0});
     },
     "animations[0].samplers[1].input: key time 1 (0.500000) does not come after key time 0"},
    {"output_count",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, 2, 0, 0});
     },
     "animations[0].samplers[0].output: 3 elements for 2 key times (expected 2: one value per key)"},
    {"cubic_output_count",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0}, "CUBICSPLINE");
     },
     "animations[0].samplers[0].output: 2 elements for 2 key times (expected 6: in-tangent, value and out-tangent"},
    {"unknown_interpolation",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0}, "BEZIER");
     },
     "animations[0].samplers[0].interpolation: 'BEZIER' (expected LINEAR, STEP or CUBICSPLINE)"},
    {"target_node_out_of_range",
     [](AnimatedQuad& q) {
         q.channel(7, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
     },
     "animations[0].channels[0].target.node: node 7 does not exist (the file has 1 nodes)"},
    {"sampler_out_of_range",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
         q.json()["animations"][0]["channels"][0]["sampler"] = 4;
     },
     "animations[0].channels[0].sampler: sampler 4 does not exist (animations[0] has 1)"},
    {"rotation_as_vec3",
     [](AnimatedQuad& q) {
         q.channel(0, "rotation", {0.0f}, {0, 0, 0, 1});
         q.json()["accessors"][3]["type"] = "VEC3";
     },
     "animations[0].samplers[0].output: accessor 3 is VEC3 (expected VEC4)"},
    {"input_not_float",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
         q.json()["accessors"][2]["componentType"] = 5125;
     },
     "animations[0].samplers[0].input: accessor 2 has componentType 5125 (expected 5126, FLOAT)"},
    {"input_missing_accessor",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
         q.json()["animations"][0]["samplers"][0]["input"] = 40;
     },
     "animations[0].samplers[0].input: accessor 40 does not exist (the file has 4)"},
    {"output_past_buffer",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
         q.json()["accessors"][3]["count"] = 1000000;
     },
     "animations[0].samplers[0].output: accessor 3 lies outside its buffer view"},
    {"output_not_finite",
     [](AnimatedQuad& q) {
         q.channel(0, "scale", {0.0f, 1.0f}, {1, 1, 1, 1, std::numeric_limits<float>::infinity(), 1});
     },
     "animations[0].samplers[0].output: element 1 is not finite"},
    {"zero_quaternion",
     [](AnimatedQuad& q) {
         q.channel(0, "rotation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, 0, 0});
     },
     "animations[0].samplers[0].output: element 1 is a zero quaternion"},
    {"matrix_node",
     [](AnimatedQuad& q) {
         q.json()["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
     },
     "animations[0].channels[0].target.node: node 0 has a matrix"},
    {"channel_without_path",
     [](AnimatedQuad& q) {
         q.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
         q.json()["animations"][0]["channels"][0]["target"].erase("path");
     },
     "animations[0].channels[0].target.path is missing"},
};

INSTANTIATE_TEST_SUITE_P(Broken, GltfAnimationErrors, testing::ValuesIn(kBroken),
                         [](const testing::TestParamInfo<Broken>& broken) { return std::string(broken.param.name); });

TEST(GltfAnimationNotes, WeightsAndUnknownPathsAreIgnoredWithANote) {
    AnimatedQuad quad;
    quad.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
    quad.channel(0, "translation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0});
    quad.json()["animations"][0]["channels"][1]["target"]["path"] = "weights";
    const fs::path path = quad.write(glint_test::temp_dir(), "weights");
    glint::GltfOptions options;
    options.shutter = glint::Shutter{0.0f, 1.0f};
    const glint::GltfScene s = glint::load_gltf_scene(path, options);
    bool noted = false;
    for (const std::string& line : s.report.ignored) noted |= line.find("morph target weights") != std::string::npos;
    EXPECT_TRUE(noted);
}

}  // namespace

TEST(GltfInstancingErrors, AttributesOfDifferentCountsAreRefusedNotReadPastTheirEnd) {
    // EXT_mesh_gpu_instancing with three translations and one scale: both loaders (with and
    // without a shutter) used to read the scales past their end (heap overflow under ASan).
    AnimatedQuad quad;
    const std::size_t translations = quad.accessor({0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3");
    const std::size_t scales = quad.accessor({1, 1, 1}, "VEC3");
    quad.json()["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"TRANSLATION", translations},
                                                                                    {"SCALE", scales}};
    const fs::path path = quad.write(glint_test::temp_dir(), "instancing_counts");
    EXPECT_NE(shutter_error(path).find("EXT_mesh_gpu_instancing attributes have 1 and 3 instances"), std::string::npos)
        << shutter_error(path);
    try {
        (void)glint::load_gltf_scene(path);
        ADD_FAILURE() << "loaded without a shutter";
    } catch (const glint::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("EXT_mesh_gpu_instancing attributes have 1 and 3 instances"),
                  std::string::npos)
            << e.what();
    }
}
