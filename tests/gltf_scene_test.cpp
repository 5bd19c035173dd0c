// Every glTF sample in shared/data: the loader's counts against the file's own JSON (read
// here independently, without Glint's reader), the camera against its node, and a tiny
// render that must be finite and not blank.

#include "glint/diagnostics.h"
#include "glint/image/film.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/assets/gltf_scene_loader.h"
#include "glint/math/constants.h"
#include "glint/scene/render_scene.h"

#include "source_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <set>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path gltf_dir() { return glint_test::kSharedDataDir / "gltf"; }

std::vector<fs::path> sample_files() {
    std::vector<fs::path> files;
    if (!fs::exists(gltf_dir())) return files;
    for (const auto& e : fs::recursive_directory_iterator(gltf_dir())) {
        const auto ext = e.path().extension();
        if (ext == ".gltf" || ext == ".glb") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

json read_json(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (path.extension() == ".glb") {
        uint32_t length = 0;
        std::memcpy(&length, bytes.data() + 12, 4);
        return json::parse(bytes.substr(20, length));
    }
    return json::parse(bytes);
}

using M4 = std::array<double, 16>;  // row-major

M4 mul(const M4& a, const M4& b) {
    M4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i * 4 + j] += a[i * 4 + k] * b[k * 4 + j];
    return r;
}

M4 local_matrix(const json& node) {
    M4 m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (node.contains("matrix")) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[r * 4 + c] = node["matrix"][c * 4 + r].get<double>();
        return m;
    }
    const json t = node.value("translation", json::array({0, 0, 0}));
    const json q = node.value("rotation", json::array({0, 0, 0, 1}));
    const json s = node.value("scale", json::array({1, 1, 1}));
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double rot[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
                           2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                           2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[r * 4 + c] = rot[r * 3 + c] * s[c].get<double>();
        m[r * 4 + 3] = t[r].get<double>();
    }
    return m;
}

/// What the JSON says a faithful loader must produce.
struct Expected {
    std::size_t meshes = 0, triangles = 0, instanced_triangles = 0, materials = 0, lights = 0, cameras = 0;
    bool has_camera = false;
    std::array<double, 3> camera_position{};
    double camera_yfov = 0.0;
    bool camera_perspective = true;
};

std::size_t mesh_triangles(const json& j, const json& mesh) {
    std::size_t n = 0;
    for (const json& p : mesh["primitives"]) {
        if (p.value("mode", 4) != 4) continue;
        const std::size_t accessor = p.contains("indices") ? p["indices"].get<std::size_t>()
                                                           : p["attributes"]["POSITION"].get<std::size_t>();
        n += j["accessors"][accessor]["count"].get<std::size_t>() / 3;
    }
    return n;
}

Expected expected_from_json(const json& j) {
    Expected e;
    e.materials = j.contains("materials") ? j["materials"].size() : 0;
    std::set<std::size_t> meshes;
    bool first_camera = true;
    std::function<void(std::size_t, const M4&)> visit = [&](std::size_t n, const M4& parent) {
        const json& node = j["nodes"][n];
        const M4 world = mul(parent, local_matrix(node));
        if (node.contains("mesh")) {
            const std::size_t mesh = node["mesh"];
            const std::size_t tris = mesh_triangles(j, j["meshes"][mesh]);
            if (meshes.insert(mesh).second) e.triangles += tris;
            std::size_t copies = 1;  // EXT_mesh_gpu_instancing: one copy per instance
            if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing"))
                for (const auto& [attribute, accessor] : node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"].items())
                    copies = std::max<std::size_t>(copies, j["accessors"][accessor.get<std::size_t>()]["count"]);
            e.instanced_triangles += tris * copies;
        }
        if (node.contains("extensions") && node["extensions"].contains("KHR_lights_punctual")) ++e.lights;
        if (node.contains("camera")) {
            ++e.cameras;
            if (first_camera) {
                first_camera = false;
                e.has_camera = true;
                e.camera_position = {world[3], world[7], world[11]};
                const json& cam = j["cameras"][node["camera"].get<std::size_t>()];
                e.camera_perspective = cam.value("type", "") != "orthographic";
                if (e.camera_perspective) e.camera_yfov = cam["perspective"]["yfov"];
            }
        }
        for (const json& c : node.value("children", json::array())) visit(c, world);
    };
    for (const json& root : j["scenes"][j.value("scene", 0)]["nodes"])
        visit(root, M4{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    e.meshes = meshes.size();
    return e;
}

class GltfSample : public testing::TestWithParam<fs::path> {};

TEST_P(GltfSample, CountsCameraAndRenderMatchTheFile) {
    const fs::path path = GetParam();
    const Expected want = expected_from_json(read_json(path));
    glint::GltfScene loaded = glint::load_gltf_scene(path);
    const glint::GltfReport& r = loaded.report;
    glint::Scene& scene = loaded.loaded.scene;

    EXPECT_EQ(r.meshes, want.meshes);
    EXPECT_EQ(r.triangles, want.triangles);
    EXPECT_EQ(r.instanced_triangles, want.instanced_triangles);
    EXPECT_EQ(r.materials, want.materials);
    EXPECT_EQ(r.lights, want.lights);
    EXPECT_EQ(r.cameras.size(), want.cameras);
    EXPECT_EQ(scene.lights().size(), want.lights > 0 ? want.lights : 1u) << "default key light when the file has none";
    for (std::size_t m = 0; m < want.materials; ++m) EXPECT_FALSE(scene.materials()[m].name.empty());

    if (want.has_camera) {
        const glint::Camera& cam = scene.camera;
        EXPECT_NEAR(cam.eye().x, want.camera_position[0], 1e-4);
        EXPECT_NEAR(cam.eye().y, want.camera_position[1], 1e-4);
        EXPECT_NEAR(cam.eye().z, want.camera_position[2], 1e-4);
        if (want.camera_perspective) {
            EXPECT_EQ(cam.projection(), glint::Projection::Perspective);
            EXPECT_NEAR(cam.vertical_fov(), want.camera_yfov * 180.0 / 3.14159265358979, 1e-3);
        } else {
            EXPECT_EQ(cam.projection(), glint::Projection::Orthographic);
        }
    }

    const glint::RenderScene prepared(std::move(scene));
    EXPECT_EQ(prepared.statistics().unique_triangles, want.triangles);
    EXPECT_EQ(prepared.statistics().instanced_triangles, want.instanced_triangles);
    glint::RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    glint::Film film(settings.width, settings.height);
    glint::WhittedIntegrator(4).render(prepared, settings, film, {});
    float lo = glint::kInfinity, hi = -glint::kInfinity;
    std::size_t bad = 0;
    for (uint32_t y = 0; y < film.height(); ++y)
        for (uint32_t x = 0; x < film.width(); ++x) {
            const glint::Color c = film.at(x, y);
            if (!c.is_finite()) ++bad;
            lo = std::min(lo, c.luminance());
            hi = std::max(hi, c.luminance());
        }
    EXPECT_EQ(bad, 0u) << "NaN or infinite pixels";
    EXPECT_GT(hi, 0.0f) << "black image";
    EXPECT_GT(hi - lo, 1e-3f) << "uniform image: the model is not visible";
}

std::string sample_name(const testing::TestParamInfo<fs::path>& info) {
    std::string name = info.param.stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(SharedData, GltfSample, testing::ValuesIn(sample_files()), sample_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GltfSample);

TEST(GltfSamples, SharedDataPresent) {
    if (!fs::exists(gltf_dir())) GTEST_SKIP() << "no shared data at " << gltf_dir();
    EXPECT_GE(sample_files().size(), 16u);
}

TEST(GltfCameras, SelectsByNameOrIndexAndRejectsUnknown) {
    const fs::path path = gltf_dir() / "Cameras/glTF/Cameras.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << "no shared data at " << path;
    const glint::GltfScene by_index = glint::load_gltf_scene(path, {"1"});
    EXPECT_EQ(by_index.loaded.scene.camera.projection(), glint::Projection::Orthographic);
    EXPECT_NEAR(by_index.loaded.scene.camera.view_height(), 2.0f, 1e-6f);  // ymag 1 is the half height
    EXPECT_THROW((void)glint::load_gltf_scene(path, {"no such camera"}), glint::SceneError);
}

}  // namespace
