#include "ply_header.h"

#include "glint/diagnostics.h"
#include "glint/util/file_extension.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

namespace glint {

std::optional<PlyScalar> ply_scalar_named(std::string_view name) {
    static constexpr std::pair<std::string_view, PlyScalar> kNames[] = {
        {"char", PlyScalar::Int8},      {"int8", PlyScalar::Int8},       {"uchar", PlyScalar::UInt8},
        {"uint8", PlyScalar::UInt8},    {"short", PlyScalar::Int16},     {"int16", PlyScalar::Int16},
        {"ushort", PlyScalar::UInt16},  {"uint16", PlyScalar::UInt16},   {"int", PlyScalar::Int32},
        {"int32", PlyScalar::Int32},    {"uint", PlyScalar::UInt32},     {"uint32", PlyScalar::UInt32},
        {"float", PlyScalar::Float32},  {"float32", PlyScalar::Float32}, {"double", PlyScalar::Float64},
        {"float64", PlyScalar::Float64}};
    for (const auto& [text, scalar] : kNames)
        if (text == name) return scalar;
    return std::nullopt;
}

std::size_t ply_scalar_size(PlyScalar type) {
    switch (type) {
        case PlyScalar::Int8:
        case PlyScalar::UInt8:
            return 1;
        case PlyScalar::Int16:
        case PlyScalar::UInt16:
            return 2;
        case PlyScalar::Int32:
        case PlyScalar::UInt32:
        case PlyScalar::Float32:
            return 4;
        case PlyScalar::Float64:
            return 8;
    }
    return 0;
}

void check_ply_header(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    const bool has_magic = bool(in.read(magic, 4));
    if (in.gcount() == 0) return;  // empty: assimp says so
    const bool ply_start = std::string_view(magic, 3) == "ply" || std::string_view(magic, 3) == "PLY";
    // assimp reads a file as PLY by its extension or by a "ply" start, and then loops
    // forever without end_header ("plyA\n..." hung; found by fuzz/fuzz_ply).
    if (!ply_start && lower_case_extension(path) != ".ply") return;  // not PLY: assimp decides
    if (!has_magic || !ply_start || !(magic[3] == '\n' || magic[3] == '\r'))
        throw SceneError(path.string() +
                         ":1: cannot read mesh file: not a PLY file (expected the first line to be 'ply')");
    in.seekg(0);
    constexpr std::size_t kMaxHeader = 1 << 20;
    bool ascii = false, ended = false;
    double needed = 0.0;  // bytes of data the counts imply; double: counts may be absurd
    double count = 0.0, per_element = 0.0;
    // At least a byte per element, even one without properties: assimp still loops over them.
    auto element_bytes = [&] { return count * std::max(per_element, 1.0); };
    std::string line;
    std::size_t line_number = 0;
    for (std::size_t read = 0; read < kMaxHeader && std::getline(in, line); read += line.size() + 1) {
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string word, a, b;
        words >> word;
        if (word == "end_header") {
            ended = true;
            break;
        }
        if (word == "format") {
            words >> a;
            ascii = a == "ascii";
        } else if (word == "element") {
            needed += element_bytes();
            unsigned long long n = 0;
            words >> a >> n;
            if (!words)
                throw SceneError(path.string() + ":" + std::to_string(line_number) + ": cannot read mesh file: PLY " +
                                 "element line '" + line + "' is malformed (expected 'element NAME COUNT' with a " +
                                 "count from 0 to " + std::to_string(std::numeric_limits<unsigned long long>::max()) +
                                 ")");
            count = double(n);
            per_element = 0.0;
        } else if (word == "property") {
            words >> a;
            const bool list = a == "list";
            if (list) words >> a >> b;  // count type, item type
            const std::optional<PlyScalar> type = ply_scalar_named(a);
            std::string name;
            words >> name;
            if (!words || !type || (list && !ply_scalar_named(b)))
                throw SceneError(path.string() + ":" + std::to_string(line_number) +
                                 ": cannot read mesh file: PLY property " + "line '" + line +
                                 "' is malformed (expected 'property TYPE NAME' or 'property list " +
                                 "COUNT_TYPE ITEM_TYPE NAME', types char uchar short ushort int uint float double or " +
                                 "int8 uint8 int16 uint16 int32 uint32 float32 float64)");
            per_element += ascii ? 2.0 : double(ply_scalar_size(*type));
        }
    }
    if (!ended)
        throw SceneError(path.string() +
                         ": cannot read mesh file: the PLY header has no end_header line (expected one " +
                         "within the first " + std::to_string(kMaxHeader >> 20) + " MB)");
    needed += element_bytes();
    const auto header_end = in.tellg();
    in.seekg(0, std::ios::end);
    const double data = double(in.tellg() - header_end);
    if (needed > data)
        throw SceneError(
            path.string() + ": cannot read mesh file: the PLY header declares elements that need at least " +
            std::to_string(static_cast<unsigned long long>(std::min(needed, 1e19))) + " bytes, but " +
            std::to_string(static_cast<long long>(data)) + " bytes follow it (truncated, or wrong counts)");
}

}  // namespace glint
