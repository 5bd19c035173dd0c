// The hand-over of an imported mesh file from the import child (src/assets/mesh_file_bytes.h):
// everything comes back as it was, and damaged bytes are refused, never trusted.
#include "assets/mesh_file_bytes.h"

#include "glint/diagnostics.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace {

glint::MeshFile sample_file() {
    glint::MeshFile file;
    glint::MeshData data;
    data.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    data.indices = {0, 1, 2, 0, 2, 3};
    data.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}};
    data.uvs = {{0, 0}, {1, 0}, {0, 1}, {0.5f, 0.5f}};
    data.tangents = {{{1, 0, 0}, 1.0f}, {{1, 0, 0}, 1.0f}, {{1, 0, 0}, 1.0f}, {{0, 1, 0}, -1.0f}};
    file.meshes.push_back(std::make_shared<glint::TriangleMesh>(data, "Cube"));
    file.meshes.push_back(nullptr);
    file.mesh_materials = {1, 0};
    glint::Matrix4 m = glint::Matrix4::identity();
    m.m[0][3] = 2.5f;
    file.placements.push_back({0, m, "Node.001"});
    file.distinct_meshes = 2;
    glint::Material red;
    red.name = "red";
    red.diffuse = {0.8f, 0.1f, 0.1f};
    red.fresnel_mirror = true;
    red.ior = 1.33f;
    red.roughness = 0.25f;
    red.base_color = {0.9f, 0.5f, 0.2f};
    red.metallic = 0.75f;
    red.absorption = glint::Color(0.5f, 1.0f, 2.0f);
    red.dielectric_f0 = glint::Color(0.02f);
    file.materials = {glint::Material{}, red};
    auto image = std::make_shared<glint::Image>(2, 1, 3);
    image->pixels = {1, 2, 3, 4, 5, 6};
    file.material_images = {nullptr, image};
    auto normals = std::make_shared<glint::Image>(1, 1, 3);
    normals->pixels = {0.5f, 0.5f, 1.0f};
    file.material_normal_images = {normals, nullptr};
    file.declared_up = glint::UpAxis::Z;
    file.warnings = {"model.obj: dropped 1 triangle"};
    file.skinned_meshes = {"Arm"};
    file.morphed_meshes = {"Face", "Brow"};
    file.animations = 3;
    file.gpu_instances = 7;
    return file;
}

std::string mesh_load_error(std::string_view bytes) {
    try {
        (void)glint::mesh_file_from_bytes(bytes, "model.obj");
    } catch (const glint::SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(MeshFileBytes, EverythingComesBackAsItWas) {
    const glint::MeshFile back = glint::mesh_file_from_bytes(glint::to_bytes(sample_file()), "model.obj");
    ASSERT_EQ(back.meshes.size(), 2u);
    ASSERT_NE(back.meshes[0], nullptr);
    EXPECT_EQ(back.meshes[1], nullptr);
    EXPECT_EQ(back.meshes[0]->name(), "Cube");
    const glint::MeshData& data = back.meshes[0]->data();
    EXPECT_EQ(data.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(data.positions[3].z, 1.0f);
    EXPECT_EQ(data.normals[3].x, 1.0f);
    EXPECT_EQ(data.uvs[3].y, 0.5f);
    ASSERT_EQ(data.tangents.size(), 4u);
    EXPECT_EQ(data.tangents[3].direction.y, 1.0f);
    EXPECT_EQ(data.tangents[3].sign, -1.0f);
    EXPECT_EQ(back.mesh_materials, (std::vector<uint32_t>{1, 0}));
    ASSERT_EQ(back.placements.size(), 1u);
    EXPECT_EQ(back.placements[0].node, "Node.001");
    EXPECT_EQ(back.placements[0].file_from_mesh.m[0][3], 2.5f);
    EXPECT_EQ(back.distinct_meshes, 2u);
    ASSERT_EQ(back.materials.size(), 2u);
    EXPECT_EQ(back.materials[1].name, "red");
    EXPECT_EQ(back.materials[1].diffuse.g, 0.1f);
    EXPECT_TRUE(back.materials[1].fresnel_mirror);
    EXPECT_FALSE(back.materials[0].fresnel_mirror);
    EXPECT_EQ(back.materials[1].ior, 1.33f);
    EXPECT_EQ(back.materials[1].roughness, 0.25f);
    EXPECT_EQ(back.materials[1].base_color, glint::Color(0.9f, 0.5f, 0.2f));
    EXPECT_EQ(back.materials[1].metallic, 0.75f);
    EXPECT_EQ(back.materials[1].absorption, glint::Color(0.5f, 1.0f, 2.0f));
    EXPECT_EQ(back.materials[1].dielectric_f0, glint::Color(0.02f));
    ASSERT_EQ(back.material_images.size(), 2u);
    EXPECT_EQ(back.material_images[0], nullptr);
    ASSERT_NE(back.material_images[1], nullptr);
    EXPECT_EQ(back.material_images[1]->width, 2);
    EXPECT_EQ(back.material_images[1]->pixels, (std::vector<float>{1, 2, 3, 4, 5, 6}));
    ASSERT_EQ(back.material_normal_images.size(), 2u);
    ASSERT_NE(back.material_normal_images[0], nullptr);
    EXPECT_EQ(back.material_normal_images[0]->pixels, (std::vector<float>{0.5f, 0.5f, 1.0f}));
    EXPECT_EQ(back.material_normal_images[1], nullptr);
    EXPECT_EQ(back.declared_up, glint::UpAxis::Z);
    EXPECT_EQ(back.warnings, sample_file().warnings);
    EXPECT_EQ(back.skinned_meshes, sample_file().skinned_meshes);
    EXPECT_EQ(back.morphed_meshes, sample_file().morphed_meshes);
    EXPECT_EQ(back.animations, 3u);
    EXPECT_EQ(back.gpu_instances, 7u);
}

TEST(MeshFileBytes, EveryCutShortRecordIsRefused) {
    const std::string bytes = glint::to_bytes(sample_file());
    for (std::size_t size = 0; size < bytes.size(); ++size)
        EXPECT_NE(mesh_load_error(std::string_view(bytes).substr(0, size))
                      .find("model.obj: the importer process handed "
                            "back damaged data"),
                  std::string::npos)
            << "cut at " << size;
    EXPECT_NE(mesh_load_error(bytes + "x").find("data after the end"), std::string::npos);
}

TEST(MeshFileBytes, AHugeCountIsRefusedBeforeAllocating) {
    std::string bytes = glint::to_bytes(sample_file());
    // The mesh count, then the first mesh's flag and name; its position count comes next.
    const std::size_t positions = sizeof(uint64_t) + 1 + sizeof(uint32_t) + 4;
    const uint64_t huge = uint64_t(1) << 60;
    std::memcpy(bytes.data() + positions, &huge, sizeof huge);
    EXPECT_NE(mesh_load_error(bytes).find("a length runs past the end of the data"), std::string::npos)
        << mesh_load_error(bytes);
}

TEST(MeshFileBytes, AMeshThatDoesNotValidateIsRefused) {
    glint::MeshFile file = sample_file();
    std::string bytes = glint::to_bytes(file);
    // The first index (after the count, flag, name, and the 4 positions with their count).
    const std::size_t first_index =
        sizeof(uint64_t) + 1 + sizeof(uint32_t) + 4 + sizeof(uint64_t) + 4 * sizeof(glint::Vec3) + sizeof(uint64_t);
    const uint32_t past_the_end = 99;
    std::memcpy(bytes.data() + first_index, &past_the_end, sizeof past_the_end);
    EXPECT_NE(mesh_load_error(bytes).find("model.obj: the importer process handed back damaged data"),
              std::string::npos)
        << mesh_load_error(bytes);
}

TEST(MeshFileBytes, AnImageWhoseSizeDoesNotMatchItsPixelsIsRefused) {
    glint::MeshFile file = sample_file();
    auto wrong = std::make_shared<glint::Image>(*file.material_images[1]);
    wrong->width = 3;
    file.material_images[1] = wrong;
    EXPECT_NE(mesh_load_error(glint::to_bytes(file)).find("an image's size does not match its pixels"),
              std::string::npos);
}
