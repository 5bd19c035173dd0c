#include "gltf_geometry.h"

#include "glint/diagnostics.h"

#include <algorithm>

#include <cstring>

namespace glint::gltf {

namespace {

std::size_t component_size(int type) {
    switch (type) {
        case 5120:
        case 5121:
            return 1;
        case 5122:
        case 5123:
            return 2;
        case 5125:
        case 5126:
            return 4;
        default:
            return 0;
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
    const auto& accessor = json.at("accessors").at(index);
    const std::string where = user + ", accessor " + std::to_string(index);
    const std::size_t element = component_size(integer<int>(accessor.at("componentType"))) *
                                component_count(accessor.at("type").get<std::string>());
    if (element == 0) fail(doc.path, where + ": unknown componentType or type");
    if (!accessor.contains("bufferView")) {
        if (accessor.contains("sparse")) return;
        fail(doc.path,
             where + ": no bufferView (compressed geometry such as KHR_draco_mesh_compression is not supported)");
    }
    const auto view_index = integer<std::size_t>(accessor.at("bufferView"));
    if (view_index >= array_size(json, "bufferViews"))
        fail(doc.path, where + ": bufferView " + std::to_string(view_index) + " does not exist");
    const auto& view = json.at("bufferViews").at(view_index);
    const auto buffer = integer<std::size_t>(view.at("buffer"));
    const std::size_t view_offset = integer_or<std::size_t>(view, "byteOffset", std::size_t(0));
    const std::size_t view_length = integer<std::size_t>(view.at("byteLength"));
    if (!fits_in(view_offset, view_length, buffer < doc.buffers.size() ? doc.buffers[buffer].size() : 0))
        fail(doc.path, where + ": bufferView " + std::to_string(view_index) + " lies outside its buffer");
    const std::size_t count = integer<std::size_t>(accessor.at("count"));
    const std::size_t stride = integer_or<std::size_t>(view, "byteStride", element);
    if (stride < element)
        fail(doc.path, where + ": byteStride " + std::to_string(stride) + " of bufferView " +
                           std::to_string(view_index) + " is smaller than an element (" + std::to_string(element) +
                           " bytes)");
    if (!elements_fit(integer_or<std::size_t>(accessor, "byteOffset", std::size_t(0)), count, stride, element,
                      view_length))
        fail(doc.path, where + ": " + std::to_string(count) + " elements do not fit in bufferView " +
                           std::to_string(view_index) + " (" + std::to_string(view_length) + " bytes)");
}

/// Number of index values of accessor `index` (already checked) that are >= `vertices`.
std::size_t count_bad_indices(const Document& doc, std::size_t index, std::size_t vertices) {
    const auto& accessor = doc.json.at("accessors").at(index);
    if (!accessor.contains("bufferView")) return 0;
    const auto& view = doc.json.at("bufferViews").at(integer<std::size_t>(accessor.at("bufferView")));
    const std::size_t size = component_size(integer<int>(accessor.at("componentType")));
    const std::size_t stride = integer_or<std::size_t>(view, "byteStride", size);
    const unsigned char* data = doc.buffers[integer<std::size_t>(view.at("buffer"))].data() +
                                integer_or<std::size_t>(view, "byteOffset", std::size_t(0)) +
                                integer_or<std::size_t>(accessor, "byteOffset", std::size_t(0));
    std::size_t bad = 0;
    for (std::size_t i = 0, n = integer<std::size_t>(accessor.at("count")); i < n; ++i) {
        uint32_t v = 0;
        std::memcpy(&v, data + i * stride, size);  // little-endian: the low bytes come first
        bad += v >= vertices;
    }
    return bad;
}

using nlohmann::json;

/// The default scene's hierarchy as a forest: "scenes" and "nodes" with names, transforms,
/// meshes and children. A child index that does not exist, a second parent or a cycle is
/// dropped (assimp would read past its node array or recurse forever), and so is a root that
/// became a child.
void add_nodes(const Document& doc, json& out) {
    const json& in = doc.json;
    const std::size_t mesh_count = array_size(in, "meshes");
    const std::size_t node_count = array_size(in, "nodes");
    std::vector<int> parent(node_count, -1);
    auto is_ancestor = [&](std::size_t candidate, std::size_t node) {
        for (int p = int(node); p >= 0; p = parent[std::size_t(p)])
            if (std::size_t(p) == candidate) return true;
        return false;
    };
    out["nodes"] = json::array();
    for (std::size_t i = 0; i < node_count; ++i) {
        const auto& node = in.at("nodes").at(i);
        json n = json::object();
        for (const char* key : {"name", "matrix", "translation", "rotation", "scale"})
            if (node.contains(key)) n[key] = node[key];
        if (node.contains("mesh")) {
            if (integer<std::size_t>(node.at("mesh")) >= mesh_count)
                fail(doc.path, "node " + std::to_string(i) + " uses mesh " +
                                   std::to_string(integer<std::size_t>(node.at("mesh"))) + ", which does not exist");
            n["mesh"] = node.at("mesh");
        }
        json children = json::array();
        for (const auto& c : node.value("children", json::array())) {
            const auto child = integer<std::size_t>(c);
            if (child >= node_count || parent[child] >= 0 || is_ancestor(child, i)) continue;
            parent[child] = int(i);
            children.push_back(child);
        }
        if (!children.empty()) n["children"] = std::move(children);
        out["nodes"].push_back(std::move(n));
    }
    if (in.contains("scene")) out["scene"] = in.at("scene");
    if (!in.contains("scenes")) return;
    out["scenes"] = json::array();
    for (const auto& scene : in.at("scenes")) {
        json roots = json::array();
        for (const auto& r : scene.value("nodes", json::array()))
            if (integer<std::size_t>(r) < node_count && parent[integer<std::size_t>(r)] < 0) roots.push_back(r);
        out["scenes"].push_back({{"nodes", std::move(roots)}});
    }
}

/// "meshes" with attributes, indices and mode only, and "accessors". Every accessor a
/// primitive uses is checked to lie inside its buffer (SceneError otherwise); index values
/// past the vertices are counted in `warnings`, and assimp drops their triangles.
void add_meshes(const Document& doc, json& out, std::vector<std::string>& warnings) {
    const json& in = doc.json;
    out["meshes"] = json::array();
    for (std::size_t m = 0, mesh_count = array_size(in, "meshes"); m < mesh_count; ++m) {
        const auto& mesh = in.at("meshes").at(m);
        json primitives = json::array();
        std::size_t p = 0;
        for (const auto& primitive : mesh.at("primitives")) {
            const std::string user = "mesh " + std::to_string(m) + " primitive " + std::to_string(p++);
            json kept = {{"attributes", primitive.at("attributes")}};
            if (!primitive.at("attributes").contains("POSITION")) fail(doc.path, user + " has no POSITION attribute");
            for (const auto& [name, accessor] : primitive.at("attributes").items())
                check_accessor(doc, integer<std::size_t>(accessor), user + " attribute " + name);
            if (primitive.contains("indices")) {
                const auto indices = integer<std::size_t>(primitive.at("indices"));
                check_accessor(doc, indices, user + " indices");
                const auto vertices =
                    in.at("accessors").at(integer<std::size_t>(primitive.at("attributes").at("POSITION"))).at("count");
                if (const std::size_t bad = count_bad_indices(doc, indices, integer<std::size_t>(vertices)); bad > 0)
                    warnings.push_back(doc.path.string() + ": " + user + ": " + std::to_string(bad) +
                                       " out-of-range vertex index(es) (expected below " +
                                       std::to_string(integer<std::size_t>(vertices)) +
                                       "); their triangles are dropped");
                kept["indices"] = indices;
            }
            if (primitive.contains("mode")) kept["mode"] = primitive.at("mode");
            primitives.push_back(std::move(kept));
        }
        json kept_mesh = {{"primitives", std::move(primitives)}};
        if (mesh.contains("name")) kept_mesh["name"] = mesh.at("name");
        out["meshes"].push_back(std::move(kept_mesh));
    }
    if (in.contains("accessors")) out["accessors"] = in.at("accessors");
}

/// The document's buffers merged into one, each 4-byte aligned, with "bufferViews" shifted
/// to match and "buffers" describing the result; returns the merged bytes.
std::string add_merged_buffer(const Document& doc, json& out) {
    std::vector<std::size_t> base;
    std::string bin;
    for (const auto& buffer : doc.buffers) {
        base.push_back(bin.size());
        bin.append(reinterpret_cast<const char*>(buffer.data()), buffer.size());
        while (bin.size() % 4) bin += '\0';
    }
    out["bufferViews"] = json::array();
    for (const auto& view : doc.json.value("bufferViews", json::array())) {
        json v = json::object();
        const auto buffer = integer<std::size_t>(view.at("buffer"));
        if (buffer >= base.size())
            fail(doc.path, "a bufferView uses buffer " + std::to_string(buffer) + ", which does not exist");
        v["buffer"] = 0;
        v["byteOffset"] = base[buffer] + integer_or<std::size_t>(view, "byteOffset", std::size_t(0));
        v["byteLength"] = view.at("byteLength");
        if (view.contains("byteStride")) v["byteStride"] = view.at("byteStride");
        out["bufferViews"].push_back(std::move(v));
    }
    out["buffers"] = json::array({{{"byteLength", bin.size()}}});
    return bin;
}

/// A GLB file (glTF 2.0 §4.4): header, JSON chunk padded with spaces, BIN chunk.
std::string pack_glb(const json& gltf, const std::string& bin) {
    std::string text = gltf.dump();
    while (text.size() % 4) text += ' ';
    auto u32 = [](std::size_t v) {
        const auto x = static_cast<uint32_t>(v);
        return std::string(reinterpret_cast<const char*>(&x), 4);
    };
    std::string glb = u32(kGlbMagic) + u32(2) + u32(12 + 8 + text.size() + 8 + bin.size());
    glb += u32(text.size()) + u32(kChunkJson) + text;
    glb += u32(bin.size()) + u32(kChunkBinary) + bin;
    return glb;
}

}  // namespace

std::string geometry_glb(const Document& doc, std::vector<std::string>& warnings) {
    json out;
    out["asset"] = {{"version", "2.0"}};
    add_nodes(doc, out);
    add_meshes(doc, out, warnings);
    const std::string bin = add_merged_buffer(doc, out);
    return pack_glb(out, bin);
}

std::vector<uint32_t> primitive_materials(const Document& doc) {
    std::vector<uint32_t> result;
    const auto none = static_cast<uint32_t>(array_size(doc.json, "materials"));
    for (const auto& mesh : doc.json.value("meshes", nlohmann::json::array()))
        for (const auto& primitive : mesh.value("primitives", nlohmann::json::array())) {
            const auto m = integer_or<std::size_t>(primitive, "material", std::size_t(none));
            result.push_back(m < none ? static_cast<uint32_t>(m) : none);
        }
    return result;
}

std::vector<Matrix4> gpu_instances(const Document& doc, const nlohmann::json& node) {
    if (!node.contains("extensions") || !node.at("extensions").contains("EXT_mesh_gpu_instancing")) return {};
    const auto& attributes =
        node.at("extensions").at("EXT_mesh_gpu_instancing").value("attributes", nlohmann::json::object());
    std::vector<float> t, r, sc;
    if (attributes.contains("TRANSLATION")) t = read_floats(doc, integer<std::size_t>(attributes.at("TRANSLATION")), 3);
    if (attributes.contains("ROTATION")) r = read_floats(doc, integer<std::size_t>(attributes.at("ROTATION")), 4);
    if (attributes.contains("SCALE")) sc = read_floats(doc, integer<std::size_t>(attributes.at("SCALE")), 3);
    // The extension requires one count for all attributes; a shorter one would be read past
    // its end.
    const std::size_t count = std::max({t.size() / 3, r.size() / 4, sc.size() / 3});
    for (const std::size_t n : {t.size() / 3, r.size() / 4, sc.size() / 3})
        if (n != 0 && n != count)
            throw SceneError(doc.path.string() + ": node '" + node.value("name", std::string()) +
                             "': EXT_mesh_gpu_instancing attributes have " + std::to_string(n) + " and " +
                             std::to_string(count) + " instances (expected the same count in every attribute)");
    std::vector<Matrix4> instances;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 translation = t.empty() ? Vec3(0.0f) : Vec3(t[3 * i], t[3 * i + 1], t[3 * i + 2]);
        const float identity[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        const float* rotation = r.empty() ? identity : &r[4 * i];
        const Vec3 scale = sc.empty() ? Vec3(1.0f) : Vec3(sc[3 * i], sc[3 * i + 1], sc[3 * i + 2]);
        instances.push_back(trs_matrix(translation, rotation, scale));
    }
    return instances;
}

/// EXT_mesh_gpu_instancing, which assimp 5.2.5 drops: the node's assimp placement is
/// replaced by one placement per instance (node · T·R·S of the instance). assimp numbers
/// its meshes glTF mesh by mesh, primitive by primitive, which gives the node's meshes.
std::size_t expand_gpu_instancing(const Document& doc, MeshFile& file) {
    const std::vector<PlacedNode> nodes = placed_nodes(doc);
    const auto& json = doc.json;
    std::vector<std::size_t> first_primitive;  // per glTF mesh, its first assimp mesh
    std::size_t next = 0;
    for (const auto& mesh : json.value("meshes", nlohmann::json::array())) {
        first_primitive.push_back(next);
        next += mesh.value("primitives", nlohmann::json::array()).size();
    }
    if (next != file.meshes.size()) return 0;  // numbering not as expected: keep assimp's placements
    std::size_t instances = 0;
    for (const PlacedNode& placed : nodes) {
        const auto& node = json.at("nodes").at(std::size_t(placed.node));
        if (!node.contains("mesh") || !node.contains("extensions") ||
            !node.at("extensions").contains("EXT_mesh_gpu_instancing"))
            continue;
        const auto mesh = integer<std::size_t>(node.at("mesh"));
        if (mesh >= first_primitive.size()) continue;
        const std::vector<Matrix4> local = gpu_instances(doc, node);
        const std::size_t count = local.size();
        if (count == 0) continue;
        const std::size_t lo = first_primitive[mesh], hi = lo + json.at("meshes").at(mesh).at("primitives").size();
        // Drop assimp's single placement of this node (same meshes, same world matrix).
        std::erase_if(file.placements, [&](const MeshPlacement& p) {
            return p.mesh >= lo && p.mesh < hi && p.file_from_mesh == placed.world_from_node;
        });
        const std::string name = node.value("name", "node" + std::to_string(placed.node));
        for (std::size_t i = 0; i < count; ++i) {
            const Matrix4 world = placed.world_from_node * local[i];
            for (std::size_t m = lo; m < hi; ++m)
                if (file.meshes[m]) file.placements.push_back({uint32_t(m), world, name + "#" + std::to_string(i)});
        }
        instances += count;
    }
    return instances;
}

}  // namespace glint::gltf
