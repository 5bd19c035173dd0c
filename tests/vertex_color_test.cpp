// Vertex colours: PLY red/green/blue and OBJ "v x y z r g b" reach the mesh as linear
// colours (decoded from sRGB, as Blender and MeshLab read them), are interpolated at a hit
// and multiply the material's base colour.

#include "test_files.h"

#include "glint/geometry/triangle_mesh.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_file.h"

#include <gtest/gtest.h>

using namespace glint;

namespace {

/// One triangle (0,0,0), (1,0,0), (0,1,0) facing +z, corners coloured red, mid grey and blue.
const char* const kColouredPly =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n"
    "0 0 0 255 0 0\n1 0 0 128 128 128\n0 1 0 0 0 255\n3 0 1 2\n";

const char* const kColouredObj = "v 0 0 0 1 0 0\nv 1 0 0 0.5019608 0.5019608 0.5019608\nv 0 1 0 0 0 1\nf 1 2 3\n";

const TriangleMesh& coloured_mesh(const Scene& scene) {
    const auto* mesh = dynamic_cast<const TriangleMesh*>(scene.objects().at(0).shape.get());
    EXPECT_NE(mesh, nullptr);
    return *mesh;
}

void expect_corner_colours(const MeshData& data, const std::string& label) {
    ASSERT_EQ(data.colors.size(), 3u) << label;
    // The vertex order may change on import: find each corner by its position.
    for (std::size_t v = 0; v < 3; ++v) {
        const Vec3& p = data.positions[v];
        const Color expected = p.x > 0.5f   ? Color(srgb_to_linear(128.0f / 255.0f))
                               : p.y > 0.5f ? Color(0.0f, 0.0f, 1.0f)
                                            : Color(1.0f, 0.0f, 0.0f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(data.colors[v][c], expected[c], 1e-4f) << label << " vertex " << v;
    }
}

}  // namespace

TEST(VertexColors, PlyAndObjColoursArriveLinear) {
    const std::filesystem::path dir = glint_test::temp_dir();
    glint_test::write_file(dir / "tri.ply", kColouredPly);
    glint_test::write_file(dir / "tri.obj", kColouredObj);
    for (const char* name : {"tri.ply", "tri.obj"}) {
        const SceneFile file = load_scene_file(dir / name);
        expect_corner_colours(coloured_mesh(file.loaded.scene).data(), name);
    }
}
