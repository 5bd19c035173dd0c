// Glint's own reader of plain binary PLY meshes (src/assets/ply_triangles.h) against
// assimp's reading of the same files: the MeshFile each gives, compared as the bytes the
// import child sends (mesh_file_bytes.h), so that every vertex, normal, index, name,
// placement and material must agree bit for bit; and the files it leaves to assimp.

#include "assets/ply_triangles.h"
#include "assets/mesh_file.h"
#include "assets/mesh_file_bytes.h"
#include "assets/ply_header.h"
#include "glint/diagnostics.h"

#include "source_paths.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using glint::MeshFile;
using glint::ReadMode;

/// What a reading gives: the MeshFile's bytes, or the error it threw.
std::string outcome(const std::function<MeshFile()>& read) {
    try {
        return glint::to_bytes(read());
    } catch (const std::exception& e) {
        return std::string("error: ") + e.what();
    }
}

/// Where two readings part, or nothing when they agree (the bytes are too long to print).
std::string difference(const std::string& plain, const std::string& assimp) {
    if (plain == assimp) return {};
    const auto at =
        std::size_t(std::mismatch(plain.begin(), plain.end(), assimp.begin(), assimp.end()).first - plain.begin());
    auto around = [at](const std::string& s) { return testing::PrintToString(s.substr(at >= 16 ? at - 16 : 0, 48)); };
    return "the readings differ from byte " + std::to_string(at) + " of " + std::to_string(plain.size()) + " / " +
           std::to_string(assimp.size()) + ": Glint's " + around(plain) + ", assimp's " + around(assimp);
}

void expect_read_natively_as_assimp_reads(const fs::path& path) {
    for (const ReadMode mode : {ReadMode::Strict, ReadMode::Lenient}) {
        SCOPED_TRACE(path.string() + (mode == ReadMode::Strict ? " (strict)" : " (lenient)"));
        const std::optional<MeshFile> plain = glint::read_plain_ply(path, mode);
        ASSERT_TRUE(plain.has_value()) << "left to assimp";
        // assimp's reading comes through the import child's byte channel, whose receiving
        // end builds the meshes again (normalising their normals once more); Glint's reading
        // is compared after the same round trip.
        const MeshFile received = glint::mesh_file_from_bytes(glint::to_bytes(*plain), path.string());
        EXPECT_EQ(difference(glint::to_bytes(received),
                             outcome([&] { return glint::read_mesh_file_with_assimp(path, mode); })),
                  "");
    }
}

void expect_left_to_assimp(const fs::path& path) {
    for (const ReadMode mode : {ReadMode::Strict, ReadMode::Lenient}) {
        SCOPED_TRACE(path.string() + (mode == ReadMode::Strict ? " (strict)" : " (lenient)"));
        EXPECT_FALSE(glint::read_plain_ply(path, mode).has_value());
        EXPECT_EQ(difference(outcome([&] { return glint::read_mesh_file(path, mode); }), outcome([&] {
                                 glint::check_ply_header(path);
                                 return glint::read_mesh_file_with_assimp(path, mode);
                             })),
                  "");
    }
}

/// `value` as the bytes of `T` in the given byte order.
template <typename T>
void put(std::string& out, T value, bool big_endian) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) out += bytes[big_endian ? sizeof(T) - 1 - i : i];
}

/// How a test writes the icosphere (tests/data/icosphere.ply) again.
struct PlyVariant {
    bool big_endian = false;
    bool doubles = false;
    bool normals = false;
    bool z_first = false;  ///< vertex properties in the order z, x, y
    std::string count_type = "uchar";
    std::string index_type = "int";
    std::string list_name = "vertex_indices";
    std::string extra_header{};           ///< lines added after the format line
    std::string extra_vertex_property{};  ///< one more float property per vertex
    int face_length = 3;                ///< the first face's index count (its extra indices repeat)
    int first_count = 0;                ///< replaces the first face's count (not its indices) when nonzero
    uint32_t first_index = 0;           ///< replaces the first face's first index when nonzero
    float first_x = 0.0f;               ///< replaces the first vertex's x when nonzero
    std::string tail{};                 ///< bytes after the faces
};

struct IcosphereData {
    std::vector<glint::Vec3> positions;
    std::vector<uint32_t> indices;
};

const IcosphereData& icosphere() {
    static const IcosphereData data = [] {
        const MeshFile file =
            glint::read_mesh_file_with_assimp(glint_test::kTestDataDir / "icosphere.ply", ReadMode::Strict);
        return IcosphereData{file.meshes[0]->data().positions, file.meshes[0]->data().indices};
    }();
    return data;
}

fs::path write_variant(const fs::path& dir, const std::string& name, const PlyVariant& variant) {
    const IcosphereData& mesh = icosphere();
    const std::string scalar = variant.doubles ? "double" : "float";
    std::string text = "ply\nformat " + std::string(variant.big_endian ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\n" + variant.extra_header + "element vertex " + std::to_string(mesh.positions.size()) +
                       "\n";
    const char* axes = variant.z_first ? "zxy" : "xyz";
    for (int k = 0; k < 3; ++k) text += "property " + scalar + " " + axes[k] + "\n";
    if (variant.normals) text += "property " + scalar + " nx\nproperty " + scalar + " ny\nproperty " + scalar + " nz\n";
    if (!variant.extra_vertex_property.empty()) text += "property float " + variant.extra_vertex_property + "\n";
    text += "element face " + std::to_string(mesh.indices.size() / 3) + "\nproperty list " + variant.count_type + " " +
            variant.index_type + " " + variant.list_name + "\nend_header\n";
    auto put_scalar = [&](float x) {
        if (variant.doubles)
            put(text, double(x) + 1e-12, variant.big_endian);  // not a float: the reader must round
        else
            put(text, x, variant.big_endian);
    };
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        glint::Vec3 p = mesh.positions[v];
        if (v == 0 && variant.first_x != 0.0f) p.x = variant.first_x;
        const int order[3] = {variant.z_first ? 2 : 0, variant.z_first ? 0 : 1, variant.z_first ? 1 : 2};
        for (const int a : order) put_scalar(p[a]);
        if (variant.normals) {
            // A length other than one, and one normal that is not finite.
            const glint::Vec3 n = v == 5 ? glint::Vec3(std::numeric_limits<float>::quiet_NaN(), 0.0f, 1.0f) : p * 3.0f;
            for (int a = 0; a < 3; ++a) put_scalar(n[a]);
        }
        if (!variant.extra_vertex_property.empty()) put(text, 0.5f, variant.big_endian);
    }
    for (std::size_t f = 0; f < mesh.indices.size() / 3; ++f) {
        const int length = f == 0 ? variant.face_length : 3;
        const int count = f == 0 && variant.first_count != 0 ? variant.first_count : length;
        if (variant.count_type == "uchar" || variant.count_type == "uint8")
            put(text, uint8_t(count), variant.big_endian);
        else
            put(text, uint32_t(count), variant.big_endian);
        for (int k = 0; k < length; ++k) {
            uint32_t index = mesh.indices[3 * f + std::min(k, 2)];
            if (f == 0 && k == 0 && variant.first_index != 0) index = variant.first_index;
            put(text, index, variant.big_endian);
        }
    }
    text += variant.tail;
    const fs::path path = dir / (name + ".ply");
    glint_test::write_file(path, text);
    return path;
}

TEST(PlyTriangles, TheExampleAndTestMeshesReadAsAssimpReadsThem) {
    expect_read_natively_as_assimp_reads(glint_test::kTestDataDir / "icosphere.ply");
    expect_read_natively_as_assimp_reads(glint_test::kScenesDir / "assets" / "stanford_bunny.ply");
}

TEST(PlyTriangles, TheSharedStanfordMeshesReadAsAssimpReadsThem) {
    const fs::path dir = glint_test::kSharedMeshDir;
    if (!fs::exists(dir / "stanford_dragon_res2.ply")) GTEST_SKIP() << "no shared meshes at " << dir;
    for (const char* name : {"stanford_bunny.ply", "stanford_dragon_res2.ply", "stanford_lucy_100k.ply"})
        expect_read_natively_as_assimp_reads(dir / name);
}

TEST(PlyTriangles, EveryByteOrderTypeAndNameReadsAsAssimpReadsIt) {
    const fs::path dir = glint_test::temp_dir();
    expect_read_natively_as_assimp_reads(
        write_variant(dir, "little", {.extra_header = "comment made by a test\nobj_info none\n"}));
    expect_read_natively_as_assimp_reads(write_variant(dir, "big", {.big_endian = true}));
    expect_read_natively_as_assimp_reads(
        write_variant(dir, "normals", {.normals = true, .count_type = "uint8", .index_type = "uint"}));
    expect_read_natively_as_assimp_reads(write_variant(dir, "doubles_big_reordered",
                                                       {.big_endian = true,
                                                        .doubles = true,
                                                        .normals = true,
                                                        .z_first = true,
                                                        .count_type = "uint",
                                                        .index_type = "uint32",
                                                        .list_name = "vertex_index"}));
}

TEST(PlyTriangles, LeavesEveryOtherFileToAssimp) {
    const fs::path dir = glint_test::temp_dir();
    expect_left_to_assimp(glint_test::kTestDataDir / "vertex_colored_triangle.ply");  // ASCII
    expect_left_to_assimp(write_variant(dir, "quad", {.face_length = 4}));
    expect_left_to_assimp(write_variant(dir, "point", {.face_length = 1}));
    // A count that is not 3 in a file whose size still fits faces of three.
    expect_left_to_assimp(write_variant(dir, "miscounted", {.first_count = 4}));
    expect_left_to_assimp(write_variant(dir, "miscounted_big", {.big_endian = true, .first_count = 2}));
    expect_left_to_assimp(write_variant(dir, "colour", {.extra_vertex_property = "red"}));
    expect_left_to_assimp(write_variant(dir, "half_normal", {.extra_vertex_property = "nx"}));
    expect_left_to_assimp(write_variant(dir, "short_indices", {.index_type = "short"}));
    expect_left_to_assimp(write_variant(dir, "other_list", {.list_name = "indices"}));
    expect_left_to_assimp(write_variant(dir, "past_the_vertices", {.first_index = 1000}));
    expect_left_to_assimp(write_variant(dir, "negative_index", {.first_index = 0xffffffffu}));  // -1 as an int
    expect_left_to_assimp(write_variant(dir, "not_finite", {.first_x = std::numeric_limits<float>::infinity()}));
    expect_left_to_assimp(write_variant(dir, "longer", {.tail = "\n"}));
    expect_left_to_assimp(write_variant(dir, "material", {.extra_header = "element material 0\n"}));
    // A header with "\r\n" line ends, and one cut inside the faces.
    std::string text = glint_test::read_file(glint_test::kTestDataDir / "icosphere.ply");
    const std::size_t header_end = text.find("end_header\n") + 11;
    std::string crlf;
    for (const char c : text.substr(0, header_end)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    glint_test::write_file(dir / "crlf.ply", crlf + text.substr(header_end));
    expect_left_to_assimp(dir / "crlf.ply");
    glint_test::write_file(dir / "cut.ply", text.substr(0, text.size() - 7));
    expect_left_to_assimp(dir / "cut.ply");
}

}  // namespace
