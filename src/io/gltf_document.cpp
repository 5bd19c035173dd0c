#include "gltf_document.h"

#include "glint/io/scene_file.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>

namespace glint::gltf {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr uint32_t kChunkBinary = 0x004E4942;   // "BIN\0"

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw SceneError(path.string() + ": " + what);
}

std::vector<unsigned char> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open the file");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

uint32_t read_u32(const std::vector<unsigned char>& bytes, std::size_t offset) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;  // GLB is little-endian, as every machine Glint targets
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
    const std::filesystem::path file = gltf.parent_path() / decoded;
    if (!std::filesystem::exists(file))
        fail(gltf, std::string(what) + " " + std::to_string(index) + " '" + uri + "' is missing (expected " +
                       file.string() + ")");
    return read_bytes(file);
}

Matrix4 node_matrix(const nlohmann::json& node) {
    Matrix4 m = Matrix4::identity();
    if (node.contains("matrix")) {
        const auto& a = node["matrix"];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m.m[r][c] = a.at(std::size_t(c * 4 + r)).get<float>();  // column-major
        return m;
    }
    Vec3 t(0.0f), s(1.0f);
    float q[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    if (node.contains("translation"))
        t = {node["translation"][0].get<float>(), node["translation"][1].get<float>(), node["translation"][2].get<float>()};
    if (node.contains("scale"))
        s = {node["scale"][0].get<float>(), node["scale"][1].get<float>(), node["scale"][2].get<float>()};
    if (node.contains("rotation"))
        for (int i = 0; i < 4; ++i) q[i] = node["rotation"][std::size_t(i)].get<float>();
    return trs_matrix(t, q, s);
}

}  // namespace

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

std::vector<float> read_floats(const Document& doc, std::size_t index, int components) {
    const auto& accessor = doc.json["accessors"].at(index);
    const std::size_t count = accessor.at("count").get<std::size_t>();
    const int type = accessor.at("componentType").get<int>();
    const std::size_t size = type == 5126 || type == 5125 ? 4 : type == 5122 || type == 5123 ? 2 : 1;
    std::vector<float> out(count * std::size_t(components), 0.0f);
    if (!accessor.contains("bufferView")) return out;  // all zeros, per spec (sparse not supported)
    const auto& view = doc.json["bufferViews"].at(accessor["bufferView"].get<std::size_t>());
    const std::size_t buffer = view.at("buffer").get<std::size_t>();
    const std::size_t element = size * std::size_t(components);
    const std::size_t stride = view.value("byteStride", element);
    const std::size_t begin = view.value("byteOffset", std::size_t(0)) + accessor.value("byteOffset", std::size_t(0));
    if (count > 0 && (buffer >= doc.buffers.size() || begin + (count - 1) * stride + element > doc.buffers[buffer].size() ||
                      begin + (count - 1) * stride + element > view.value("byteOffset", std::size_t(0)) + view.at("byteLength").get<std::size_t>()))
        fail(doc.path, "accessor " + std::to_string(index) + " lies outside its buffer view");
    const unsigned char* data = doc.buffers[buffer].data() + begin;
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < components; ++c) {
            const unsigned char* p = data + i * stride + std::size_t(c) * size;
            float v = 0.0f;
            switch (type) {
                case 5126: std::memcpy(&v, p, 4); break;
                case 5120: v = std::max(float(*reinterpret_cast<const int8_t*>(p)) / 127.0f, -1.0f); break;
                case 5121: v = float(*p) / 255.0f; break;
                case 5122: { int16_t x; std::memcpy(&x, p, 2); v = std::max(float(x) / 32767.0f, -1.0f); break; }
                case 5123: { uint16_t x; std::memcpy(&x, p, 2); v = float(x) / 65535.0f; break; }
                default: fail(doc.path, "accessor " + std::to_string(index) + " has component type " + std::to_string(type) + " (expected float or normalized integers)");
            }
            out[i * std::size_t(components) + std::size_t(c)] = v;
        }
    return out;
}

namespace {

std::size_t component_size(int type) {
    switch (type) {
        case 5120: case 5121: return 1;
        case 5122: case 5123: return 2;
        case 5125: case 5126: return 4;
        default: return 0;
    }
}

std::size_t component_count(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    return 0;
}

/// Check that accessor `index`, used by `user`, has data inside its buffer.
void check_accessor(const Document& doc, std::size_t index, const std::string& user) {
    const auto& json = doc.json;
    if (index >= array_size(json, "accessors"))
        fail(doc.path, user + " uses accessor " + std::to_string(index) + ", which does not exist");
    const auto& accessor = json["accessors"][index];
    const std::string where = user + ", accessor " + std::to_string(index);
    const std::size_t element = component_size(accessor.at("componentType").get<int>()) *
                                component_count(accessor.at("type").get<std::string>());
    if (element == 0) fail(doc.path, where + ": unknown componentType or type");
    if (!accessor.contains("bufferView")) {
        if (accessor.contains("sparse")) return;
        fail(doc.path, where + ": no bufferView (compressed geometry such as KHR_draco_mesh_compression is not supported)");
    }
    const auto view_index = accessor["bufferView"].get<std::size_t>();
    if (view_index >= array_size(json, "bufferViews"))
        fail(doc.path, where + ": bufferView " + std::to_string(view_index) + " does not exist");
    const auto& view = json["bufferViews"][view_index];
    const auto buffer = view.at("buffer").get<std::size_t>();
    const std::size_t view_offset = view.value("byteOffset", std::size_t(0));
    const std::size_t view_length = view.at("byteLength").get<std::size_t>();
    if (buffer >= doc.buffers.size() || view_offset + view_length > doc.buffers[buffer].size())
        fail(doc.path, where + ": bufferView " + std::to_string(view_index) + " lies outside its buffer");
    const std::size_t count = accessor.at("count").get<std::size_t>();
    const std::size_t stride = view.value("byteStride", element);
    if (count > 0 && accessor.value("byteOffset", std::size_t(0)) + (count - 1) * stride + element > view_length)
        fail(doc.path, where + ": " + std::to_string(count) + " elements do not fit in bufferView " +
                           std::to_string(view_index) + " (" + std::to_string(view_length) + " bytes)");
}

/// Number of index values of accessor `index` (already checked) that are >= `vertices`.
std::size_t count_bad_indices(const Document& doc, std::size_t index, std::size_t vertices) {
    const auto& accessor = doc.json["accessors"][index];
    if (!accessor.contains("bufferView")) return 0;
    const auto& view = doc.json["bufferViews"][accessor["bufferView"].get<std::size_t>()];
    const std::size_t size = component_size(accessor["componentType"].get<int>());
    const std::size_t stride = view.value("byteStride", size);
    const unsigned char* data = doc.buffers[view["buffer"].get<std::size_t>()].data() +
                                view.value("byteOffset", std::size_t(0)) + accessor.value("byteOffset", std::size_t(0));
    std::size_t bad = 0;
    for (std::size_t i = 0, n = accessor["count"].get<std::size_t>(); i < n; ++i) {
        uint32_t v = 0;
        std::memcpy(&v, data + i * stride, size);  // little-endian: the low bytes come first
        bad += v >= vertices;
    }
    return bad;
}

}  // namespace

std::string geometry_glb(const Document& doc, std::vector<std::string>& warnings) {
    using nlohmann::json;
    const json& in = doc.json;
    json out;
    out["asset"] = {{"version", "2.0"}};
    if (in.contains("scene")) out["scene"] = in["scene"];
    if (in.contains("scenes")) {
        out["scenes"] = json::array();
        for (const auto& scene : in["scenes"]) out["scenes"].push_back({{"nodes", scene.value("nodes", json::array())}});
    }
    const std::size_t mesh_count = array_size(in, "meshes");
    const std::size_t node_count = array_size(in, "nodes");
    // The hierarchy must be a forest: a child index that does not exist, a second parent or a
    // cycle is dropped (assimp would read past the array or recurse forever).
    std::vector<int> parent(node_count, -1);
    auto is_ancestor = [&](std::size_t candidate, std::size_t node) {
        for (int p = int(node); p >= 0; p = parent[std::size_t(p)])
            if (std::size_t(p) == candidate) return true;
        return false;
    };
    out["nodes"] = json::array();
    for (std::size_t i = 0; i < node_count; ++i) {
        const auto& node = in["nodes"][i];
        json n = json::object();
        for (const char* key : {"name", "matrix", "translation", "rotation", "scale"})
            if (node.contains(key)) n[key] = node[key];
        if (node.contains("mesh")) {
            if (node["mesh"].get<std::size_t>() >= mesh_count)
                fail(doc.path, "node " + std::to_string(i) + " uses mesh " + std::to_string(node["mesh"].get<std::size_t>()) +
                                   ", which does not exist");
            n["mesh"] = node["mesh"];
        }
        json children = json::array();
        for (const auto& c : node.value("children", json::array())) {
            const auto child = c.get<std::size_t>();
            if (child >= node_count || parent[child] >= 0 || is_ancestor(child, i)) continue;
            parent[child] = int(i);
            children.push_back(child);
        }
        if (!children.empty()) n["children"] = std::move(children);
        out["nodes"].push_back(std::move(n));
    }
    if (out.contains("scenes"))
        for (auto& scene : out["scenes"]) {
            json roots = json::array();
            for (const auto& r : scene["nodes"])
                if (r.get<std::size_t>() < node_count && parent[r.get<std::size_t>()] < 0) roots.push_back(r);
            scene["nodes"] = std::move(roots);
        }
    out["meshes"] = json::array();
    for (std::size_t m = 0; m < mesh_count; ++m) {
        const auto& mesh = in["meshes"][m];
        json primitives = json::array();
        std::size_t p = 0;
        for (const auto& primitive : mesh.at("primitives")) {
            const std::string user = "mesh " + std::to_string(m) + " primitive " + std::to_string(p++);
            json kept = {{"attributes", primitive.at("attributes")}};
            if (!primitive["attributes"].contains("POSITION")) fail(doc.path, user + " has no POSITION attribute");
            for (const auto& [name, accessor] : primitive["attributes"].items())
                check_accessor(doc, accessor.get<std::size_t>(), user + " attribute " + name);
            if (primitive.contains("indices")) {
                const auto indices = primitive["indices"].get<std::size_t>();
                check_accessor(doc, indices, user + " indices");
                const auto vertices = in["accessors"][primitive["attributes"]["POSITION"].get<std::size_t>()]["count"];
                if (const std::size_t bad = count_bad_indices(doc, indices, vertices.get<std::size_t>()); bad > 0)
                    warnings.push_back(doc.path.string() + ": " + user + ": " + std::to_string(bad) +
                                       " out-of-range vertex index(es) (expected below " +
                                       std::to_string(vertices.get<std::size_t>()) + "); their triangles are dropped");
                kept["indices"] = indices;
            }
            if (primitive.contains("mode")) kept["mode"] = primitive["mode"];
            primitives.push_back(std::move(kept));
        }
        json kept_mesh = {{"primitives", std::move(primitives)}};
        if (mesh.contains("name")) kept_mesh["name"] = mesh["name"];
        out["meshes"].push_back(std::move(kept_mesh));
    }
    if (in.contains("accessors")) out["accessors"] = in["accessors"];

    // One merged buffer: every buffer 4-byte aligned, bufferViews shifted to match.
    std::vector<std::size_t> base;
    std::string bin;
    for (const auto& buffer : doc.buffers) {
        base.push_back(bin.size());
        bin.append(reinterpret_cast<const char*>(buffer.data()), buffer.size());
        while (bin.size() % 4) bin += '\0';
    }
    out["bufferViews"] = json::array();
    for (const auto& view : in.value("bufferViews", json::array())) {
        json v = json::object();
        const auto buffer = view.at("buffer").get<std::size_t>();
        if (buffer >= base.size()) fail(doc.path, "a bufferView uses buffer " + std::to_string(buffer) + ", which does not exist");
        v["buffer"] = 0;
        v["byteOffset"] = base[buffer] + view.value("byteOffset", std::size_t(0));
        v["byteLength"] = view.at("byteLength");
        if (view.contains("byteStride")) v["byteStride"] = view["byteStride"];
        out["bufferViews"].push_back(std::move(v));
    }
    out["buffers"] = json::array({{{"byteLength", bin.size()}}});

    std::string text = out.dump();
    while (text.size() % 4) text += ' ';
    auto u32 = [](std::size_t v) {
        const auto x = static_cast<uint32_t>(v);
        return std::string(reinterpret_cast<const char*>(&x), 4);
    };
    std::string glb = "glTF" + u32(2) + u32(12 + 8 + text.size() + 8 + bin.size());
    glb += u32(text.size()) + u32(kChunkJson) + text;
    glb += u32(bin.size()) + u32(kChunkBinary) + bin;
    return glb;
}

std::vector<uint32_t> primitive_materials(const Document& doc) {
    std::vector<uint32_t> result;
    const auto none = static_cast<uint32_t>(array_size(doc.json, "materials"));
    for (const auto& mesh : doc.json.value("meshes", nlohmann::json::array()))
        for (const auto& primitive : mesh.value("primitives", nlohmann::json::array())) {
            const auto m = primitive.value("material", std::size_t(none));
            result.push_back(m < none ? static_cast<uint32_t>(m) : none);
        }
    return result;
}

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
        if (bytes.size() < 20) fail(path, "truncated GLB: " + std::to_string(bytes.size()) + " bytes (expected a 12-byte header and a JSON chunk)");
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
        doc.json = nlohmann::json::parse(json_text);
    } catch (const nlohmann::json::exception& e) {
        fail(path, std::string("invalid glTF JSON: ") + e.what());
    }
    if (!doc.json.is_object() || !doc.json.contains("asset")) fail(path, "not a glTF 2.0 file (no \"asset\" object)");
    const std::string version = doc.json["asset"].value("version", "");
    if (version.rfind("2.", 0) != 0) fail(path, "glTF version '" + version + "' (expected 2.x)");

    const std::size_t buffer_count = array_size(doc.json, "buffers");
    for (std::size_t b = 0; b < buffer_count; ++b) {
        const auto& buffer = doc.json["buffers"][b];
        const std::size_t declared = buffer.value("byteLength", std::size_t(0));
        std::vector<unsigned char> data;
        if (buffer.contains("uri")) {
            data = read_uri(path, buffer["uri"].get<std::string>(), "buffer", b);
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

std::vector<PlacedNode> placed_nodes(const Document& doc) {
    const auto& json = doc.json;
    const std::size_t node_count = array_size(json, "nodes");
    std::vector<int> roots;
    const std::size_t scene_count = array_size(json, "scenes");
    if (scene_count > 0) {
        const std::size_t scene = std::min<std::size_t>(json.value("scene", 0u), scene_count - 1);
        for (const auto& n : json["scenes"][scene].value("nodes", nlohmann::json::array())) roots.push_back(n.get<int>());
    } else {
        std::vector<bool> is_child(node_count, false);
        for (const auto& node : json.value("nodes", nlohmann::json::array()))
            for (const auto& c : node.value("children", nlohmann::json::array()))
                if (c.get<std::size_t>() < node_count) is_child[c.get<std::size_t>()] = true;
        for (std::size_t i = 0; i < node_count; ++i)
            if (!is_child[i]) roots.push_back(int(i));
    }
    std::vector<PlacedNode> placed;
    std::vector<bool> on_path(node_count, false);  // guards against cycles in broken files
    std::function<void(int, const Matrix4&)> visit = [&](int n, const Matrix4& parent) {
        if (n < 0 || std::size_t(n) >= node_count || on_path[std::size_t(n)]) return;
        on_path[std::size_t(n)] = true;
        const auto& node = json["nodes"][std::size_t(n)];
        const Matrix4 world = parent * node_matrix(node);
        placed.push_back({n, world});
        for (const auto& c : node.value("children", nlohmann::json::array())) visit(c.get<int>(), world);
        on_path[std::size_t(n)] = false;
    };
    for (int r : roots) visit(r, Matrix4::identity());
    return placed;
}

std::vector<unsigned char> image_bytes(const Document& doc, int index, std::string& name) {
    const auto& image = doc.json["images"].at(std::size_t(index));
    const std::string mime = image.value("mimeType", "");
    if (image.contains("uri")) {
        const std::string uri = image["uri"].get<std::string>();
        name = uri.rfind("data:", 0) == 0 ? (uri.find("image/jpeg") != std::string::npos ? "image.jpg" : "image.png")
                                           : uri;
        return read_uri(doc.path, uri, "image", std::size_t(index));
    }
    const auto view_index = image.at("bufferView").get<std::size_t>();
    const auto& view = doc.json["bufferViews"].at(view_index);
    const auto buffer = view.at("buffer").get<std::size_t>();
    const std::size_t offset = view.value("byteOffset", std::size_t(0)), length = view.at("byteLength").get<std::size_t>();
    if (buffer >= doc.buffers.size() || offset + length > doc.buffers[buffer].size())
        fail(doc.path, "image " + std::to_string(index) + ": bufferView " + std::to_string(view_index) +
                           " lies outside its buffer");
    name = "image" + std::to_string(index) + (mime == "image/jpeg" ? ".jpg" : ".png");
    const auto* begin = doc.buffers[buffer].data() + offset;
    return {begin, begin + length};
}

}  // namespace glint::gltf
