// Normal maps: tangent frames of meshes (MikkTSpace's convention, glTF's handedness), the
// bent normal against its closed form, a rendered quad whose shading follows the mapped
// normal exactly as an analytically tilted surface would, in both integrators; glTF's
// normalTexture and its scale; normal maps that are not RGB refused.

#include "glint/assets/gltf_scene_loader.h"
#include "glint/diagnostics.h"
#include "glint/geometry/tangent_space.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/materials/normal_map.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "gltf_texture_files.h"
#include "test_files.h"

#include <gtest/gtest.h>


#include <cmath>
#include <string>

using namespace glint;

namespace {

/// A unit square in the xy plane facing +z, corners top-left, top-right, bottom-right,
/// bottom-left, with texture coordinates as glTF stores them (v = 0 at the top of the image:
/// +y on the surface is "up" in the image).
MeshData square(bool mirrored_u) {
    MeshData d;
    d.positions = {Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 0)};
    d.indices = {0, 3, 2, 0, 2, 1};
    d.normals.assign(4, Vec3(0, 0, 1));
    d.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
    if (mirrored_u)
        for (Vec2& uv : d.uvs) uv.x = 1.0f - uv.x;
    return d;
}

/// The texel that encodes tangent-space normal `n` (unit): rgb = (n + 1)/2.
Color encoded(const Vec3& n) { return {0.5f * (n.x + 1.0f), 0.5f * (n.y + 1.0f), 0.5f * (n.z + 1.0f)}; }

void expect_direction_near(const Vec3& got, const Vec3& want, float tolerance, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tolerance) << what;
    EXPECT_NEAR(got.y, want.y, tolerance) << what;
    EXPECT_NEAR(got.z, want.z, tolerance) << what;
}

}  // namespace

TEST(TangentSpace, TangentsFollowUAndTheSignMakesGreenPointUpInTheImage) {
    const std::vector<Tangent> plain = compute_tangents(square(false));
    ASSERT_EQ(plain.size(), 4u);
    for (const Tangent& t : plain) {
        expect_direction_near(t.direction, Vec3(1, 0, 0), 1e-6f, "tangent along +u = +x");
        // b = sign·(n × t) = +y: the image's top.
        EXPECT_EQ(t.sign, 1.0f);
    }
    // Mirrored in u: the tangent turns to −x, and the sign keeps b = +y.
    for (const Tangent& t : compute_tangents(square(true))) {
        expect_direction_near(t.direction, Vec3(-1, 0, 0), 1e-6f, "mirrored tangent");
        EXPECT_EQ(t.sign, -1.0f);
    }
    MeshData no_uvs = square(false);
    no_uvs.uvs.clear();
    EXPECT_TRUE(compute_tangents(no_uvs).empty());
}

TEST(TangentSpace, TangentsAreMadePerpendicularToTheVertexNormal) {
    MeshData d = square(false);
    const Vec3 tilted = normalize(Vec3(0.5f, 0, 1));
    d.normals.assign(4, tilted);
    for (const Tangent& t : compute_tangents(d)) {
        EXPECT_NEAR(dot(t.direction, tilted), 0.0f, 1e-6f);
        EXPECT_NEAR(length(t.direction), 1.0f, 1e-6f);
    }
}

TEST(NormalMap, BendsTheNormalInTheTangentFrameWithGltfsScale) {
    // A constant map of n = (0.3, 0.2, 1)/|…|: with scale s the bent normal is
    // normalize(s·0.3·t + s·0.2·b + n) with t = +x, b = +y, n = +z (glTF 2.0 §3.9.3).
    const Vec3 stored = normalize(Vec3(0.3f, 0.2f, 1.0f));
    const CheckerTexture constant(encoded(stored), encoded(stored), 1.0f);
    Material m;
    m.normal_texture = &constant;
    SurfaceInteraction si;
    si.geometric_normal = si.shading_normal = Vec3(0, 0, 1);
    si.dpdu = Vec3(2, 0, 0);   // +u along +x
    si.dpdv = Vec3(0, -2, 0);  // +v down the image: −y
    for (float scale : {1.0f, 2.0f, 0.5f}) {
        m.normal_scale = scale;
        const Vec3 want = normalize(Vec3(stored.x * scale, stored.y * scale, stored.z));
        expect_direction_near(normal_mapped(m, si), want, 1e-5f, "from ∂p/∂u, scale " + std::to_string(scale));
    }
    // A vertex tangent takes precedence; its sign −1 turns green downwards.
    m.normal_scale = 1.0f;
    si.tangent = Vec3(1, 0, 0);
    si.tangent_sign = -1.0f;
    expect_direction_near(normal_mapped(m, si), Vec3(stored.x, -stored.y, stored.z), 1e-5f, "vertex tangent, sign −1");
}

TEST(NormalMap, NeverBendsBelowTheTrueSurface) {
    const Vec3 sideways = normalize(Vec3(-1, 0, 0.05f));  // towards the side the shading normal leans to
    const CheckerTexture constant(encoded(sideways), encoded(sideways), 1.0f);
    Material m;
    m.normal_texture = &constant;
    m.normal_scale = 5.0f;  // x scaled far past z
    SurfaceInteraction si;
    si.geometric_normal = Vec3(0, 0, 1);
    si.shading_normal = normalize(Vec3(-0.3f, 0, 1));
    si.dpdu = Vec3(1, 0, 0);
    si.dpdv = Vec3(0, -1, 0);
    const Vec3 n = normal_mapped(m, si);
    EXPECT_GT(dot(n, si.geometric_normal), 0.0f);
    EXPECT_NEAR(length(n), 1.0f, 1e-5f);
}

namespace {

/// A square facing the camera (+z), lit by a directional light from `light_dir`, kd = 1, on
/// black: its pixels are kd·E·cos(n, l) in both integrators, nothing else reaching it.
std::string lit_square(const std::string& material_keys) {
    return R"(
[render]
width = 8
height = 8
spp = 1
max_depth = 2

[camera]
position = [0, 0, 5]
look_at = [0, 0, 0]
fov = 10

[[lights]]
type = "directional"
direction = [-0.4, -0.3, -1]
intensity = 1

[[textures]]
name = "bumps"
type = "image"
file = "normals.exr"
encoding = "data"

[[materials]]
name = "surface"
ambient = 0
diffuse = 1
)" + material_keys + R"(

[[objects]]
type = "quad"
corner = [-2, -2, 0]
edge_u = [4, 0, 0]
edge_v = [0, 4, 0]
material = "surface"
)";
}

float centre_pixel(const std::string& text, const std::filesystem::path& dir, const std::string& integrator) {
    LoadedScene loaded = load_toml_scene_string(text, "square.toml", dir);
    loaded.settings.integrator = integrator;
    const RenderScene scene(std::move(loaded.scene));
    Film film(loaded.settings.width, loaded.settings.height);
    make_integrator(loaded.settings)->render(scene, loaded.settings, film);
    return film.at(4, 4).g;
}

}  // namespace

TEST(NormalMap, AFlatSquareShadesLikeTheTiltedSurfaceItsMapDescribes) {
    // The quad's u runs along +x and its v along +y (edge_v), so the image's "up" (−v) is −y:
    // a map texel n = (a, b, c) is the world normal (a, −b, c). The lit pixel over the unmapped
    // one is cos(n, l)/cos(z, l): the shading of a square tilted to that normal.
    const auto dir = glint_test::temp_dir();
    const Vec3 stored = normalize(Vec3(-0.35f, 0.25f, 1.0f));
    Image map(4, 4, 3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const Color c = encoded(stored);
            map.at(x, y, 0) = c.r;
            map.at(x, y, 1) = c.g;
            map.at(x, y, 2) = c.b;
        }
    write_image(dir / "normals.exr", map);
    const Vec3 l = normalize(Vec3(0.4f, 0.3f, 1.0f));  // towards the light
    const Vec3 world = normalize(Vec3(stored.x, -stored.y, stored.z));
    const float want = dot(world, l) / dot(Vec3(0, 0, 1), l);
    for (const char* integrator : {"whitted", "path"}) {
        const float flat = centre_pixel(lit_square(""), dir, integrator);
        const float mapped = centre_pixel(lit_square("normal_texture = \"bumps\""), dir, integrator);
        ASSERT_GT(flat, 0.0f) << integrator;
        EXPECT_NEAR(mapped / flat, want, 1e-4f) << integrator;
    }
}

TEST(NormalMap, ATomlNormalMapMustHaveThreeChannels) {
    const auto dir = glint_test::temp_dir();
    write_image(dir / "normals.exr", Image(2, 2, 1));
    try {
        (void)load_toml_scene_string(lit_square("normal_texture = \"bumps\""), "square.toml", dir);
        FAIL() << "a one-channel normal map was accepted";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("square.toml:28:18:", 0), 0u) << message;
        EXPECT_NE(message.find("three channels (RGB)"), std::string::npos) << message;
        EXPECT_NE(message.find("has 1"), std::string::npos) << message;
    }
}

namespace {

glint::GltfScene gltf_quad(const nlohmann::json& normal_texture, int channels = 3) {
    const auto dir = glint_test::temp_dir();
    if (channels == 3) {
        glint_test::write_png(dir / "normals.png", {{200, 90, 230}});
    } else {
        glint_test::write_png8(dir / "normals.png", 1, 1, 1, {128});
    }
    nlohmann::json material = {{"pbrMetallicRoughness", {{"metallicFactor", 0}}}};
    if (!normal_texture.is_null()) material["normalTexture"] = normal_texture;
    return glint::load_gltf_scene(glint_test::write_gltf(dir, "quad", glint_test::quad_json_with(material, {"normals.png"})));
}

}  // namespace

TEST(GltfNormalTexture, IsReadAsLinearDataWithItsScale) {
    const glint::GltfScene plain = gltf_quad(nullptr);
    EXPECT_EQ(plain.loaded.scene.materials()[0].normal_texture, nullptr);
    const glint::GltfScene mapped = gltf_quad({{"index", 0}, {"scale", 0.5}});
    const Material& m = mapped.loaded.scene.materials()[0];
    ASSERT_NE(m.normal_texture, nullptr);
    EXPECT_EQ(m.normal_scale, 0.5f);
    // Linear: 200/255 stays 0.784 (sRGB decoding would make it 0.578).
    EXPECT_NEAR(m.normal_texture->evaluate(Vec2(0.5f, 0.5f), Vec3()).r, 200.0f / 255.0f, 1e-4f);
    for (const std::string& line : mapped.report.ignored)
        EXPECT_EQ(line.find("normalTexture"), std::string::npos) << line;
}

TEST(GltfNormalTexture, AnImageThatIsNotRgbIsRefusedNamingItsPath) {
    try {
        (void)gltf_quad({{"index", 0}}, 1);
        FAIL() << "a one-channel normal map was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("materials[0].normalTexture: its image has 1 channel(s)"), std::string::npos)
            << e.what();
    }
}
