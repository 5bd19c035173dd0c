#include "gltf_document.h"

#include "glint/diagnostics.h"
#include "glint/util/byte_order.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>

namespace glint::gltf {

void fail(const std::filesystem::path& path, const std::string& what) { throw SceneError(path.string() + ": " + what); }

namespace {

std::vector<unsigned char> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open the file");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

uint32_t read_u32(const std::vector<unsigned char>& bytes, std::size_t offset) {
    return little_endian_u32(bytes.data() + offset);
}

std::vector<unsigned char> decode_base64(std::string_view text) {
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+' || c == '-') return 62;
        if (c == '/' || c == '_') return 63;
        return -1;
    };
    std::vector<unsigned char> out;
    out.reserve(text.size() * 3 / 4);
    uint32_t acc = 0;
    int bits = 0;
    for (char c : text) {
        const int v = value(c);
        if (v < 0) continue;  // padding and whitespace
        acc = (acc << 6) | uint32_t(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>((acc >> bits) & 0xFF));
        }
    }
    return out;
}

/// A URI that is either a data URI or a path relative to the glTF file (percent-escapes decoded).
std::vector<unsigned char> read_uri(const std::filesystem::path& gltf, const std::string& uri, const char* what,
                                    std::size_t index) {
    if (uri.rfind("data:", 0) == 0) {
        const auto comma = uri.find(',');
        if (comma == std::string::npos || uri.find(";base64") == std::string::npos)
            fail(gltf, std::string(what) + " " + std::to_string(index) + ": unsupported data URI (expected base64)");
        return decode_base64(std::string_view(uri).substr(comma + 1));
    }
    std::string decoded;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            decoded += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    // The operating system would read "a%00b.bin" as "a", a different file.
    if (decoded.find('\0') != std::string::npos)
        fail(gltf, std::string(what) + " " + std::to_string(index) + " '" + uri +
                       "': %00 in a file name (expected a relative path without NUL characters)");
    const std::filesystem::path file = gltf.parent_path() / decoded;
    std::error_code ec;  // a folder "exists" too, and reading one throws a message that names no file
    if (!std::filesystem::is_regular_file(file, ec))
        fail(gltf, std::string(what) + " " + std::to_string(index) + " '" + uri + "' is missing (expected the file " +
                       file.string() + ")");
    return read_bytes(file);
}

}  // namespace

Matrix4 node_matrix(const nlohmann::json& node) {
    Matrix4 m = Matrix4::identity();
    if (node.contains("matrix")) {
        const auto& a = node.at("matrix");
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m.m[r][c] = a.at(std::size_t(c * 4 + r)).get<float>();  // column-major
        return m;
    }
    Vec3 t(0.0f), s(1.0f);
    float q[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    if (node.contains("translation"))
        t = {node.at("translation").at(0).get<float>(), node.at("translation").at(1).get<float>(),
             node.at("translation").at(2).get<float>()};
    if (node.contains("scale"))
        s = {node.at("scale").at(0).get<float>(), node.at("scale").at(1).get<float>(),
             node.at("scale").at(2).get<float>()};
    if (node.contains("rotation"))
        for (int i = 0; i < 4; ++i) q[i] = node.at("rotation").at(std::size_t(i)).get<float>();
    return trs_matrix(t, q, s);
}

Matrix4 trs_matrix(const Vec3& t, const float q[4], const Vec3& s) {
    Matrix4 m = Matrix4::identity();
    const float x = q[0], y = q[1], z = q[2], w = q[3];
    const float r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                           {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                           {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m.m[i][j] = r[i][j] * s[j];
        m.m[i][3] = t[i];
    }
    return m;
}

bool fits_in(std::size_t offset, std::size_t length, std::size_t size) {
    return offset <= size && length <= size - offset;
}

bool elements_fit(std::size_t offset, std::size_t count, std::size_t stride, std::size_t element, std::size_t length) {
    // offset + (count - 1)·stride + element <= length, without the wrap-around a hostile
    // count or offset would get from writing it so (stride >= element >= 1). Even with no
    // elements the offset must lie inside: the reader forms data + offset.
    if (offset > length) return false;
    return count == 0 || (fits_in(offset, element, length) && count - 1 <= (length - offset - element) / stride);
}

std::vector<float> read_floats(const Document& doc, std::size_t index, int components) {
    const auto& accessor = doc.json.at("accessors").at(index);
    const std::size_t count = integer<std::size_t>(accessor.at("count"));
    const int type = integer<int>(accessor.at("componentType"));
    const std::size_t size = type == 5126 || type == 5125 ? 4 : type == 5122 || type == 5123 ? 2 : 1;
    if (!accessor.contains("bufferView")) {  // all zeros, per spec (sparse not supported)
        if (count > kMaxZeroAccessor)
            fail(doc.path, "accessor " + std::to_string(index) + " has " + std::to_string(count) +
                               " elements and no data (expected at most " + std::to_string(kMaxZeroAccessor) + ")");
        return std::vector<float>(count * std::size_t(components), 0.0f);
    }
    const auto& view = doc.json.at("bufferViews").at(integer<std::size_t>(accessor.at("bufferView")));
    const std::size_t buffer = integer<std::size_t>(view.at("buffer"));
    const std::size_t element = size * std::size_t(components);
    const std::size_t stride = integer_or<std::size_t>(view, "byteStride", element);
    const std::size_t view_offset = integer_or<std::size_t>(view, "byteOffset", std::size_t(0));
    const std::size_t view_length = integer<std::size_t>(view.at("byteLength"));
    const std::size_t offset = integer_or<std::size_t>(accessor, "byteOffset", std::size_t(0));
    if (buffer >= doc.buffers.size() || !fits_in(view_offset, view_length, doc.buffers[buffer].size()) ||
        stride < element || !elements_fit(offset, count, stride, element, view_length))
        fail(doc.path, "accessor " + std::to_string(index) + " lies outside its buffer view");
    std::vector<float> out(count * std::size_t(components), 0.0f);
    const unsigned char* data = doc.buffers[buffer].data() + view_offset + offset;
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < components; ++c) {
            const unsigned char* p = data + i * stride + std::size_t(c) * size;
            float v = 0.0f;
            switch (type) {
                case 5126:
                    std::memcpy(&v, p, 4);
                    break;
                case 5120:
                    v = std::max(float(*reinterpret_cast<const int8_t*>(p)) / 127.0f, -1.0f);
                    break;
                case 5121:
                    v = float(*p) / 255.0f;
                    break;
                case 5122: {
                    int16_t x;
                    std::memcpy(&x, p, 2);
                    v = std::max(float(x) / 32767.0f, -1.0f);
                    break;
                }
                case 5123: {
                    uint16_t x;
                    std::memcpy(&x, p, 2);
                    v = float(x) / 65535.0f;
                    break;
                }
                default:
                    fail(doc.path, "accessor " + std::to_string(index) + " has component type " + std::to_string(type) +
                                       " (expected float or normalized integers)");
            }
            out[i * std::size_t(components) + std::size_t(c)] = v;
        }
    return out;
}

std::string json_error_text(const std::exception& error) {
    const std::string_view text = error.what();
    const std::size_t end_of_prefix = text.starts_with("[json.exception.") ? text.find("] ") : text.npos;
    return std::string(end_of_prefix == text.npos ? text : text.substr(end_of_prefix + 2));
}

namespace {

/// A JSON syntax error as "file:LINE:COL: invalid glTF JSON: WHY", so that editors jump to
/// it; in a GLB the lines count within the JSON chunk, so they are named as such.
std::string parse_failure(const std::filesystem::path& path, const nlohmann::json::exception& error, bool binary) {
    // nlohmann words it "parse error at line L, column C: WHY". Parsed by hand: std::regex
    // recurses per character and overflowed the stack on a long WHY (found by fuzz_gltf).
    const std::string text = json_error_text(error);
    unsigned line = 0, column = 0;
    int consumed = 0;
    if (std::sscanf(text.c_str(), "parse error at line %u, column %u: %n", &line, &column, &consumed) != 2 ||
        consumed == 0)
        return path.string() + ": invalid glTF JSON: " + text;
    const std::string why = text.substr(std::size_t(consumed));
    if (binary)
        return path.string() + ": invalid glTF JSON chunk at line " + std::to_string(line) + ", column " +
               std::to_string(column) + ": " + why;
    return path.string() + ":" + std::to_string(line) + ":" + std::to_string(column) + ": invalid glTF JSON: " + why;
}

}  // namespace

std::size_t array_size(const nlohmann::json& json, const char* key) {
    return json.contains(key) && json[key].is_array() ? json[key].size() : 0;
}

Document read_document(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) fail(path, "no such file");
    Document doc;
    doc.path = path;
    const std::vector<unsigned char> bytes = read_bytes(path);
    std::vector<unsigned char> bin_chunk;
    bool has_bin_chunk = false;
    std::string json_text;
    doc.binary = bytes.size() >= 4 && read_u32(bytes, 0) == kGlbMagic;
    if (doc.binary) {
        if (bytes.size() < 20)
            fail(path, "truncated GLB: " + std::to_string(bytes.size()) +
                           " bytes (expected a 12-byte header and a JSON chunk)");
        const uint32_t version = read_u32(bytes, 4), length = read_u32(bytes, 8);
        if (version != 2) fail(path, "GLB version " + std::to_string(version) + " (expected 2)");
        if (length > bytes.size())
            fail(path, "truncated GLB: the header says " + std::to_string(length) + " bytes but the file has " +
                           std::to_string(bytes.size()));
        std::size_t offset = 12;
        for (int chunk = 0; offset + 8 <= length; ++chunk) {
            const uint32_t chunk_length = read_u32(bytes, offset), type = read_u32(bytes, offset + 4);
            if (offset + 8 + std::size_t(chunk_length) > length)
                fail(path, "truncated GLB: chunk " + std::to_string(chunk) + " runs past the end of the file");
            const auto* begin = bytes.data() + offset + 8;
            if (chunk == 0 && type != kChunkJson) fail(path, "GLB does not start with a JSON chunk");
            if (type == kChunkJson && chunk == 0) json_text.assign(begin, begin + chunk_length);
            if (type == kChunkBinary && !has_bin_chunk) {
                bin_chunk.assign(begin, begin + chunk_length);
                has_bin_chunk = true;
            }
            offset += 8 + std::size_t(chunk_length);
        }
    } else {
        json_text.assign(bytes.begin(), bytes.end());
    }
    try {
        // nlohmann parses iteratively but copies and prints recursively, so a deeply nested
        // file (found by fuzz_gltf) is refused here rather than overflowing the stack later.
        doc.json = nlohmann::json::parse(json_text, [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
            if (depth > kMaxNesting) fail(path, "JSON nested deeper than " + std::to_string(kMaxNesting) + " levels");
            return true;
        });
    } catch (const nlohmann::json::exception& e) {
        throw SceneError(parse_failure(path, e, doc.binary));
    }
    if (!doc.json.is_object() || !doc.json.contains("asset")) fail(path, "not a glTF 2.0 file (no \"asset\" object)");
    const std::string version = doc.json.at("asset").value("version", "");
    if (version.rfind("2.", 0) != 0) fail(path, "glTF version '" + version + "' (expected 2.x)");

    const std::size_t buffer_count = array_size(doc.json, "buffers");
    for (std::size_t b = 0; b < buffer_count; ++b) {
        const auto& buffer = doc.json.at("buffers").at(b);
        const std::size_t declared = integer_or<std::size_t>(buffer, "byteLength", std::size_t(0));
        std::vector<unsigned char> data;
        if (buffer.contains("uri")) {
            data = read_uri(path, buffer.at("uri").get<std::string>(), "buffer", b);
        } else if (b == 0 && has_bin_chunk) {
            data = std::move(bin_chunk);
        } else {
            fail(path, "buffer " + std::to_string(b) + " has no uri and no GLB BIN chunk");
        }
        if (data.size() < declared)
            fail(path, "buffer " + std::to_string(b) + " is truncated: " + std::to_string(data.size()) +
                           " bytes (expected byteLength " + std::to_string(declared) + ")");
        doc.buffers.push_back(std::move(data));
    }
    return doc;
}

std::vector<PlacedNode> placed_nodes(const Document& doc, const std::vector<Matrix4>* local) {
    const auto& json = doc.json;
    const std::size_t node_count = array_size(json, "nodes");
    std::vector<int> roots;
    const std::size_t scene_count = array_size(json, "scenes");
    if (scene_count > 0) {
        const std::size_t scene = std::min<std::size_t>(integer_or<std::size_t>(json, "scene", 0), scene_count - 1);
        for (const auto& n : json.at("scenes").at(scene).value("nodes", nlohmann::json::array()))
            roots.push_back(integer<int>(n));
    } else {
        std::vector<bool> is_child(node_count, false);
        for (const auto& node : json.value("nodes", nlohmann::json::array()))
            for (const auto& c : node.value("children", nlohmann::json::array()))
                if (integer<std::size_t>(c) < node_count) is_child[integer<std::size_t>(c)] = true;
        for (std::size_t i = 0; i < node_count; ++i)
            if (!is_child[i]) roots.push_back(int(i));
    }
    std::vector<PlacedNode> placed;
    std::vector<bool> on_path(node_count, false);  // guards against cycles in broken files
    std::function<void(int, int, const Matrix4&)> visit = [&](int n, int parent_index, const Matrix4& parent) {
        if (n < 0 || std::size_t(n) >= node_count || on_path[std::size_t(n)]) return;
        on_path[std::size_t(n)] = true;
        const auto& node = json.at("nodes").at(std::size_t(n));
        const Matrix4 world = parent * (local ? local->at(std::size_t(n)) : node_matrix(node));
        const int index = int(placed.size());
        placed.push_back({n, world, parent_index});
        for (const auto& c : node.value("children", nlohmann::json::array())) visit(integer<int>(c), index, world);
        on_path[std::size_t(n)] = false;
    };
    for (int r : roots) visit(r, -1, Matrix4::identity());
    return placed;
}

std::vector<unsigned char> image_bytes(const Document& doc, int index, std::string& name) {
    const auto& image = doc.json.at("images").at(std::size_t(index));
    const std::string mime = image.value("mimeType", "");
    if (image.contains("uri")) {
        const std::string uri = image.at("uri").get<std::string>();
        name = uri.rfind("data:", 0) == 0 ? (uri.find("image/jpeg") != std::string::npos ? "image.jpg" : "image.png")
                                          : uri;
        return read_uri(doc.path, uri, "image", std::size_t(index));
    }
    const auto view_index = integer<std::size_t>(image.at("bufferView"));
    const auto& view = doc.json.at("bufferViews").at(view_index);
    const auto buffer = integer<std::size_t>(view.at("buffer"));
    const std::size_t offset = integer_or<std::size_t>(view, "byteOffset", std::size_t(0)),
                      length = integer<std::size_t>(view.at("byteLength"));
    if (buffer >= doc.buffers.size() || !fits_in(offset, length, doc.buffers[buffer].size()))
        fail(doc.path, "image " + std::to_string(index) + ": bufferView " + std::to_string(view_index) +
                           " lies outside its buffer");
    name = "image" + std::to_string(index) + (mime == "image/jpeg" ? ".jpg" : ".png");
    const auto* begin = doc.buffers[buffer].data() + offset;
    return {begin, begin + length};
}

}  // namespace glint::gltf
