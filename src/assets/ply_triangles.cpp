#include "ply_triangles.h"

#include "ply_header.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

namespace {

/// Reads the scalar at `p` as a double; every type's values are exact in double.
using ScalarReader = double (*)(const char* p);

/// A `T` stored big-endian when `Swap` (this reader runs on little-endian machines only).
template <typename T, bool Swap>
double read_scalar(const char* p) {
    char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if constexpr (Swap) std::reverse(b, b + sizeof(T));
    T value;
    std::memcpy(&value, b, sizeof(T));
    return static_cast<double>(value);
}

template <bool Swap>
ScalarReader reader_of(PlyScalar type) {
    switch (type) {
        case PlyScalar::Int8:
            return read_scalar<int8_t, Swap>;
        case PlyScalar::UInt8:
            return read_scalar<uint8_t, Swap>;
        case PlyScalar::Int16:
            return read_scalar<int16_t, Swap>;
        case PlyScalar::UInt16:
            return read_scalar<uint16_t, Swap>;
        case PlyScalar::Int32:
            return read_scalar<int32_t, Swap>;
        case PlyScalar::UInt32:
            return read_scalar<uint32_t, Swap>;
        case PlyScalar::Float32:
            return read_scalar<float, Swap>;
        case PlyScalar::Float64:
            return read_scalar<double, Swap>;
    }
    return read_scalar<uint8_t, Swap>;
}

/// The reader of one property, chosen once per file: choosing it per value (a switch and a
/// byte loop for each of a scan's millions of scalars) was most of the load.
ScalarReader scalar_reader(PlyScalar type, bool big_endian) {
    return big_endian ? reader_of<true>(type) : reader_of<false>(type);
}

struct Property {
    std::string name;
    PlyScalar type = PlyScalar::Float32;
    std::optional<PlyScalar> list_count;  ///< set for a list property
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    bool big_endian = false;
    std::vector<Element> elements;
    std::size_t data_offset = 0;
};

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

/// The header of a binary PLY file whose every line this reader understands; nothing
/// otherwise (ASCII, "\r\n" line ends, unknown keywords or types).
std::optional<Header> binary_header(std::string_view bytes) {
    Header header;
    bool format_seen = false;
    std::size_t at = 0, line_number = 0;
    for (;;) {
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos) return std::nullopt;
        const std::string_view line = bytes.substr(at, end - at);
        at = end + 1;
        if (line.find('\r') != std::string_view::npos) return std::nullopt;
        if (line_number++ == 0) {
            if (line != "ply") return std::nullopt;
            continue;
        }
        const std::vector<std::string_view> words = words_of(line);
        if (words.empty()) return std::nullopt;
        if (words[0] == "end_header" && words.size() == 1) break;
        if (words[0] == "comment" || words[0] == "obj_info") continue;
        if (words[0] == "format") {
            if (format_seen || words.size() != 3 || words[2] != "1.0") return std::nullopt;
            if (words[1] != "binary_little_endian" && words[1] != "binary_big_endian") return std::nullopt;
            header.big_endian = words[1] == "binary_big_endian";
            format_seen = true;
        } else if (words[0] == "element" && words.size() == 3) {
            Element element{std::string(words[1]), 0, {}};
            for (const char c : words[2]) {
                if (c < '0' || c > '9' || element.count > std::numeric_limits<uint64_t>::max() / 10 - 1)
                    return std::nullopt;
                element.count = element.count * 10 + uint64_t(c - '0');
            }
            header.elements.push_back(std::move(element));
        } else if (words[0] == "property" && !header.elements.empty()) {
            Property property;
            if (words.size() == 3 && ply_scalar_named(words[1])) {
                property = {std::string(words[2]), *ply_scalar_named(words[1]), std::nullopt};
            } else if (words.size() == 5 && words[1] == "list" && ply_scalar_named(words[2]) &&
                       ply_scalar_named(words[3])) {
                property = {std::string(words[4]), *ply_scalar_named(words[3]), ply_scalar_named(words[2])};
            } else {
                return std::nullopt;
            }
            header.elements.back().properties.push_back(std::move(property));
        } else {
            return std::nullopt;
        }
    }
    if (!format_seen) return std::nullopt;
    header.data_offset = at;
    return header;
}

bool is_index_type(PlyScalar s) { return s == PlyScalar::Int32 || s == PlyScalar::UInt32; }
bool is_count_type(PlyScalar s) { return s == PlyScalar::UInt8 || is_index_type(s); }

/// Reads a data section record by record, in pieces of about 256 KiB: the file's bytes are
/// never held whole next to the arrays made from them (3.8 MB of page faults for the
/// dragon), and each piece is still in cache when it is parsed.
class RecordReader {
public:
    explicit RecordReader(std::ifstream& in) : in_(in) {}

    /// Calls `each(index, record)` for `count` records of `size` bytes, in order; false when
    /// the file ends early or `each` returns false.
    template <typename Each>
    bool for_each(std::size_t count, std::size_t size, const Each& each) {
        constexpr std::size_t kPieceBytes = std::size_t(256) << 10;
        const std::size_t per_piece = std::max<std::size_t>(1, kPieceBytes / size);
        buffer_.resize(std::min(count, per_piece) * size);
        for (std::size_t first = 0; first < count; first += per_piece) {
            const std::size_t n = std::min(per_piece, count - first);
            if (!in_.read(buffer_.data(), std::streamsize(n * size))) return false;
            const char* p = buffer_.data();
            for (std::size_t i = 0; i < n; ++i, p += size)
                if (!each(first + i, p)) return false;
        }
        return true;
    }

private:
    std::ifstream& in_;
    std::vector<char> buffer_;
};

/// A PLY file carries no material. assimp describes it as white, diffuse and specular,
/// which convert_assimp_material (assimp_import.cpp) makes this Material; the same here, so
/// that a mesh without a scene material looks as it did when assimp read every PLY file.
Material assimp_default_ply_material() {
    Material m;
    m.name = "material0";
    m.diffuse = Color(1.0f);
    m.ambient = m.diffuse;
    m.specular = Color(1.0f);
    return m;
}

}  // namespace

std::optional<MeshFile> read_plain_ply(const std::filesystem::path& path, ReadMode mode) {
    // The header first, from the file's start: any other file (OBJ, glTF, an ASCII PLY) is
    // left to assimp without being read whole.
    constexpr std::uintmax_t kHeaderBytes = 64 << 10;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::string start(std::min(size, kHeaderBytes), '\0');
    if (!in.read(start.data(), std::streamsize(start.size()))) return std::nullopt;
    const std::optional<Header> header = binary_header(start);
    if (!header || header->elements.size() != 2) return std::nullopt;
    const Element& vertices = header->elements[0];
    const Element& faces = header->elements[1];
    if (vertices.name != "vertex" || faces.name != "face" || vertices.count == 0 || faces.count == 0 ||
        vertices.count > std::numeric_limits<uint32_t>::max())
        return std::nullopt;

    // Where each vertex property lies in its record; x, y, z needed, nx, ny, nz all or none.
    constexpr std::string_view kNames[6] = {"x", "y", "z", "nx", "ny", "nz"};
    std::size_t offset[6] = {}, record = 0;
    PlyScalar type[6] = {};
    bool present[6] = {};
    for (const Property& property : vertices.properties) {
        const auto* name = std::find(std::begin(kNames), std::end(kNames), property.name);
        if (name == std::end(kNames) || property.list_count || property.type < PlyScalar::Float32) return std::nullopt;
        const auto k = std::size_t(name - std::begin(kNames));
        if (present[k]) return std::nullopt;
        present[k] = true;
        offset[k] = record;
        type[k] = property.type;
        record += ply_scalar_size(property.type);
    }
    const bool has_normals = present[3] && present[4] && present[5];
    if (!present[0] || !present[1] || !present[2] || (!has_normals && (present[3] || present[4] || present[5])))
        return std::nullopt;

    if (faces.properties.size() != 1) return std::nullopt;
    const Property& list = faces.properties[0];
    if (!list.list_count || !is_count_type(*list.list_count) || !is_index_type(list.type) ||
        (list.name != "vertex_indices" && list.name != "vertex_index"))
        return std::nullopt;
    // Three indices per face is the only layout read here, so the data's size is known
    // before it is read; any other size (other face lengths, a cut or a longer file) is
    // left to assimp.
    const std::size_t count_size = ply_scalar_size(*list.list_count), index_size = ply_scalar_size(list.type);
    const std::size_t face_record = count_size + 3 * index_size;
    const uint64_t available = size - header->data_offset;
    if (vertices.count > available / record || faces.count > available / face_record ||
        vertices.count * record + faces.count * face_record != available)
        return std::nullopt;
    if (!in.seekg(std::streamoff(header->data_offset))) return std::nullopt;

    ScalarReader read[6] = {};
    for (int k = 0; k < (has_normals ? 6 : 3); ++k) read[k] = scalar_reader(type[k], header->big_endian);
    const ScalarReader read_count = scalar_reader(*list.list_count, header->big_endian);
    const ScalarReader read_index = scalar_reader(list.type, header->big_endian);
    // The common layout, little-endian float coordinates and faces of a one-byte count and
    // four-byte indices, is read in place, without the readers' indirect call for every
    // scalar (the 1x1 dragon: 0.9 ms less, docs/performance.md). Both ways give the same
    // values.
    const int vertex_scalars = has_normals ? 6 : 3;
    const bool float_vertices = !header->big_endian && std::all_of(type, type + vertex_scalars,
                                                                   [](PlyScalar t) { return t == PlyScalar::Float32; });
    const bool plain_faces = !header->big_endian && count_size == 1 && index_size == 4;
    const bool signed_indices = list.type == PlyScalar::Int32;
    MeshData data;
    const auto vertex_count = static_cast<uint32_t>(vertices.count);
    data.positions.resize(vertex_count);
    if (has_normals) data.normals.resize(vertex_count);
    RecordReader records(in);
    const bool vertices_read = records.for_each(vertex_count, record, [&](std::size_t v, const char* p) {
        float value[6];
        for (int k = 0; k < vertex_scalars; ++k) {
            if (float_vertices)
                std::memcpy(&value[k], p + offset[k], sizeof(float));
            else
                value[k] = float(read[k](p + offset[k]));
        }
        data.positions[v] = Vec3(value[0], value[1], value[2]);
        if (!is_finite(data.positions[v])) return false;
        if (has_normals) {
            // As convert_mesh (assimp_import.cpp) takes a non-finite normal.
            const Vec3 normal(value[3], value[4], value[5]);
            data.normals[v] = is_finite(normal) ? normal : Vec3(0.0f);
        }
        return true;
    });
    if (!vertices_read) return std::nullopt;
    data.indices.resize(3 * faces.count);
    const bool faces_read = records.for_each(faces.count, face_record, [&](std::size_t f, const char* p) {
        if (plain_faces) {
            if (p[0] != 3) return false;
            uint32_t index[3];
            std::memcpy(index, p + 1, sizeof index);
            for (std::size_t k = 0; k < 3; ++k) {
                // A negative int32 is at least 2^31 as a uint32, and may still be in range.
                if ((signed_indices && int32_t(index[k]) < 0) || index[k] >= vertex_count) return false;
                data.indices[3 * f + k] = index[k];
            }
            return true;
        }
        if (read_count(p) != 3.0) return false;
        for (std::size_t k = 0; k < 3; ++k) {
            const double index = read_index(p + count_size + k * index_size);
            if (!(index >= 0.0 && index < double(vertex_count))) return false;
            data.indices[3 * f + k] = static_cast<uint32_t>(index);
        }
        return true;
    });
    if (!faces_read || in.peek() != std::ifstream::traits_type::eof()) return std::nullopt;

    const bool lenient = mode == ReadMode::Lenient;
    if (lenient && !has_normals) compute_smooth_normals(data);
    MeshFile file;
    file.meshes.push_back(std::make_shared<TriangleMesh>(std::move(data), "mesh0"));
    file.mesh_materials = {0};
    file.placements = {MeshPlacement{0, Matrix4::identity(), ""}};
    file.distinct_meshes = 1;
    if (lenient) {
        file.materials = {assimp_default_ply_material()};
        file.material_images = {nullptr};
        file.material_normal_images = {nullptr};
    }
    return file;
}

}  // namespace glint
