// What mesh files declare about their surfaces' frames and orientation, read as Blender reads
// them: glTF's TANGENT attribute (its w the handedness) instead of computed tangents; OBJ's
// `norm` and `map_Bump` as tangent-space normal maps (a grey height map ignored, said so);
// and the up axis an FBX file's GlobalSettings declare standing the automatic camera upright.
#include "gltf_test_files.h"
#include "test_files.h"

#include "glint/assets/gltf_scene_loader.h"
#include "glint/assets/mesh_loader.h"
#include "glint/image/image_io.h"
#include "glint/math/color.h"
#include "glint/scene/render_scene.h"

#include "source_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace {

using glint_test::temp_dir;
using glint_test::write_file;

/// The quad of gltf_test_files.h with NORMAL (+y), TEXCOORD_0 and, if `tangent_w` is not 0,
/// a TANGENT of (+x, tangent_w) at every vertex.
std::filesystem::path quad_with_tangents(const std::filesystem::path& dir, float tangent_w) {
    nlohmann::json json = glint_test::quad_json("quad.bin");
    std::string bin = glint_test::quad_buffer();
    glint_test::add_quad_attribute(json, bin, "NORMAL", "VEC3", {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0});
    glint_test::add_quad_attribute(json, bin, "TEXCOORD_0", "VEC2", {0, 0, 0, 1, 1, 1, 1, 0});
    const float w = tangent_w;
    if (w != 0.0f)
        glint_test::add_quad_attribute(json, bin, "TANGENT", "VEC4", {1, 0, 0, w, 1, 0, 0, w, 1, 0, 0, w, 1, 0, 0, w});
    const auto path = dir / (tangent_w < 0 ? "mirrored.glb" : tangent_w > 0 ? "tangents.glb" : "computed.glb");
    write_file(path, glint_test::make_glb(json, bin));
    return path;
}

const glint::TriangleMesh& only_mesh(const glint::Scene& scene) {
    EXPECT_EQ(scene.objects().size(), 1u);
    return dynamic_cast<const glint::TriangleMesh&>(*scene.objects().at(0).shape);
}

}  // namespace

TEST(AssetTangentFrames, AGltfTangentAttributeIsUsedWithItsHandedness) {
    const auto dir = temp_dir();
    // The quad's uvs run +u along +x and +v along +z; the image's "up" (decreasing v) is -z,
    // and +y × +x = -z, so the computed frame has sign +1. A file may say otherwise (a
    // mirrored uv layout baked elsewhere): its w = -1 must win.
    for (const float w : {-1.0f, 1.0f}) {
        const glint::GltfScene file = glint::load_gltf_scene(quad_with_tangents(dir, w));
        const glint::MeshData& data = only_mesh(file.loaded.scene).data();
        ASSERT_EQ(data.tangents.size(), 4u);
        for (const glint::Tangent& t : data.tangents) {
            EXPECT_EQ(t.sign, w);
            EXPECT_NEAR(t.direction.x, 1.0f, 1e-6f);
        }
    }
    const glint::GltfScene computed = glint::load_gltf_scene(quad_with_tangents(dir, 0.0f));
    for (const glint::Tangent& t : only_mesh(computed.loaded.scene).data().tangents) EXPECT_EQ(t.sign, 1.0f);
}

TEST(AssetTangentFrames, TheAvocadosOwnTangentsAgreeWithTheComputedOnes) {
    // Khronos' Avocado was exported with MikkTSpace tangents; Glint's own (computed when a
    // file has none) must agree: the same handedness everywhere, directions within a degree.
    const std::filesystem::path path = glint_test::kSharedDataDir / "gltf/Avocado/glTF/Avocado.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "no shared data at " << path;
    const glint::GltfScene file = glint::load_gltf_scene(path);
    glint::MeshData data = only_mesh(file.loaded.scene).data();
    const std::vector<glint::Tangent> stored = data.tangents;
    data.tangents.clear();
    const std::vector<glint::Tangent> computed = glint::compute_tangents(data);
    ASSERT_EQ(stored.size(), computed.size());
    ASSERT_GT(stored.size(), 400u);
    double angles = 0.0;
    for (std::size_t v = 0; v < stored.size(); ++v) {
        EXPECT_EQ(stored[v].sign, computed[v].sign) << "vertex " << v;
        angles += std::acos(std::min(1.0f, glint::dot(stored[v].direction, computed[v].direction)));
    }
    EXPECT_LT(angles / double(stored.size()) * 180.0 / 3.14159265358979, 1.0) << "mean angle in degrees";
}

namespace {

/// A unit square in the z = 0 plane facing +z with uvs, using material "m" of `mtl`.
std::filesystem::path obj_square(const std::filesystem::path& dir, const std::string& mtl) {
    write_file(dir / "square.mtl", "newmtl m\nKd 1 1 1\n" + mtl);
    write_file(dir / "square.obj",
               "mtllib square.mtl\nusemtl m\n"
               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
               "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
               "vn 0 0 1\n"
               "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
    return dir / "square.obj";
}

/// The material the square's one object is drawn with.
const glint::Material& square_material(const glint::LoadedScene& loaded) {
    const glint::Scene& scene = loaded.scene;
    return scene.materials().at(scene.objects().at(0).material);
}

}  // namespace

TEST(AssetTangentFrames, ObjNormAndMapBumpAreNormalMapsReadAsData) {
    const auto dir = temp_dir();
    // write_image sRGB-encodes a PNG: red 0.25 is stored as the byte of linear_to_srgb(0.25).
    // A normal map is data: that byte must come back as it is, not decoded back to 0.25.
    glint::Image bent(1, 1, 3);
    bent.pixels = {0.25f, 0.5f, 1.0f};
    glint::write_image(dir / "bent.png", bent);
    const float stored_red = glint::linear_to_srgb(0.25f);
    for (const std::string statement : {"norm bent.png\n", "map_Bump bent.png\n", "bump bent.png\n"}) {
        const glint::LoadedScene loaded = glint::load_mesh_scene(obj_square(dir, statement));
        const glint::Material& m = square_material(loaded);
        ASSERT_NE(m.normal_texture, nullptr) << statement;
        const glint::Color texel = m.normal_texture->evaluate({0.5f, 0.5f}, {});
        EXPECT_NEAR(texel.r, stored_red, 0.5f / 255.0f) << statement;
        EXPECT_NEAR(texel.b, 1.0f, 1e-6f) << statement;
    }
    const glint::LoadedScene plain = glint::load_mesh_scene(obj_square(dir, ""));
    EXPECT_EQ(square_material(plain).normal_texture, nullptr);
    // -bm, the strength, becomes the normal map's scale (glTF's normalTexture.scale).
    for (const std::string statement : {"norm -bm 0.5 bent.png\n", "map_Bump -bm 0.5 bent.png\n"}) {
        const glint::LoadedScene strength = glint::load_mesh_scene(obj_square(dir, statement));
        EXPECT_NE(square_material(strength).normal_texture, nullptr) << statement;
        EXPECT_EQ(square_material(strength).normal_scale, 0.5f) << statement;
    }
}

TEST(AssetTangentFrames, AGreyBumpMapIsAHeightMapIgnoredWithAWarning) {
    const auto dir = temp_dir();
    glint::write_image(dir / "height.png", glint::Image(2, 2, 1));
    const glint::LoadedScene loaded = glint::load_mesh_scene(obj_square(dir, "map_Bump height.png\n"));
    EXPECT_EQ(square_material(loaded).normal_texture, nullptr);
    const auto& warnings = loaded.warnings;
    EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
        return w.find("material 'm': normal map ignored: it has 1 channel(s), a height map") != std::string::npos;
    })) << (warnings.empty() ? "no warning" : warnings.front());
}

namespace {

/// A one-triangle ASCII FBX 7.4 file whose GlobalSettings declare `up_axis` (0, 1, 2 for x,
/// y, z) with `up_sign`.
std::filesystem::path fbx_triangle(const std::filesystem::path& dir, int up_axis, int up_sign) {
    const std::string name = "up" + std::to_string(up_axis) + (up_sign < 0 ? "neg" : "") + ".fbx";
    write_file(dir / name, R"(; FBX 7.4.0 project file
FBXHeaderExtension:  {
	FBXHeaderVersion: 1003
	FBXVersion: 7400
}
GlobalSettings:  {
	Version: 1000
	Properties70:  {
		P: "UpAxis", "int", "Integer", "",)" + std::to_string(up_axis) + R"(
		P: "UpAxisSign", "int", "Integer", "",)" + std::to_string(up_sign) + R"(
		P: "UnitScaleFactor", "double", "Number", "",1
	}
}
Objects:  {
	Geometry: 1000, "Geometry::Tri", "Mesh" {
		Vertices: *9 {
			a: 0,0,0,1,0,0,0,0,1
		}
		PolygonVertexIndex: *3 {
			a: 0,1,-3
		}
		GeometryVersion: 124
	}
	Model: 2000, "Model::Tri", "Mesh" {
		Version: 232
	}
}
Connections:  {
	C: "OO",1000,2000
	C: "OO",2000,0
}
)");
    return dir / name;
}

}  // namespace

/// The world axis the camera's up vector (tilted by the framing camera's look from slightly
/// above) leans along most: 0, 1, 2 for x, y, z.
int camera_up_axis(const glint::LoadedScene& loaded) {
    const glint::Vec3 up = loaded.scene.camera.up();
    EXPECT_GT(glint::max_component(glint::abs(up)), 0.9f);
    return glint::max_axis(up);
}

TEST(AssetTangentFrames, AnFbxFilesDeclaredUpAxisStandsTheAutomaticCameraUpright) {
    const auto dir = temp_dir();
    EXPECT_EQ(camera_up_axis(glint::load_mesh_scene(fbx_triangle(dir, 2, 1))), 2);
    EXPECT_EQ(camera_up_axis(glint::load_mesh_scene(fbx_triangle(dir, 1, 1))), 1);
    EXPECT_EQ(camera_up_axis(glint::load_mesh_scene(fbx_triangle(dir, 0, 1))), 0);
    // A downward axis is not one the framing camera takes: +y, as for files that declare none.
    EXPECT_EQ(camera_up_axis(glint::load_mesh_scene(fbx_triangle(dir, 2, -1))), 1);
    // --up wins over the file.
    EXPECT_EQ(camera_up_axis(glint::load_mesh_scene(fbx_triangle(dir, 2, 1), glint::UpAxis::Y)), 1);
}
