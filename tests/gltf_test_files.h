#pragma once
// Small glTF files written by tests: a 20×20 quad in the y = 0 plane facing +y, with
// whatever lights, cameras and materials a test adds to the JSON.

#include "test_files.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace glint_test {

/// The quad's JSON (one node "quad", mesh 0, material 0 white Lambertian) and its buffer.
inline nlohmann::json quad_json(const std::string& bin_name) {
    return nlohmann::json::parse(R"({
      "asset": {"version": "2.0"},
      "scene": 0,
      "scenes": [{"nodes": [0]}],
      "nodes": [{"name": "quad", "mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
      "materials": [{"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1],
                     "metallicFactor": 0, "roughnessFactor": 1}}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
         "min": [-10, 0, -10], "max": [10, 0, 10]},
        {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
      "buffers": [{"uri": ")" + bin_name +
                                 R"(", "byteLength": 72}]
    })");
}

inline std::string quad_buffer() {
    const float positions[12] = {-10, 0, -10, -10, 0, 10, 10, 0, 10, 10, 0, -10};
    const uint32_t indices[6] = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +y
    std::string bytes(72, '\0');
    std::memcpy(bytes.data(), positions, 48);
    std::memcpy(bytes.data() + 48, indices, 24);
    return bytes;
}

/// Write `json` as dir/name.gltf next to the quad's buffer dir/name.bin (the buffer's uri
/// is pointed at it).
inline std::filesystem::path write_gltf(const std::filesystem::path& dir, const std::string& name,
                                        nlohmann::json json) {
    write_file(dir / (name + ".bin"), quad_buffer());
    if (json.contains("buffers") && json["buffers"][0].contains("uri")) json["buffers"][0]["uri"] = name + ".bin";
    const auto path = dir / (name + ".gltf");
    write_file(path, json.dump(2));
    return path;
}

/// Append `floats` (the quad's 4 vertices, each a `type`: "VEC2", "VEC3", "VEC4") to `bin`
/// as a new buffer view and accessor, and make it the quad's `attribute` (replacing one it
/// had); the buffer's byteLength follows. For files written with make_glb.
inline void add_quad_attribute(nlohmann::json& json, std::string& bin, const std::string& attribute,
                               const std::string& type, const std::vector<float>& floats) {
    const std::size_t bytes = floats.size() * sizeof(float);
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}});
    json["accessors"].push_back(
        {{"bufferView", json["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", 4}, {"type", type}});
    json["meshes"][0]["primitives"][0]["attributes"][attribute] = json["accessors"].size() - 1;
    bin.append(reinterpret_cast<const char*>(floats.data()), bytes);
    json["buffers"][0]["byteLength"] = bin.size();
}

/// Pack a .gltf's JSON and one buffer into GLB bytes.
inline std::string make_glb(nlohmann::json json, const std::string& bin) {
    json["buffers"][0].erase("uri");
    std::string text = json.dump();
    while (text.size() % 4) text += ' ';
    std::string padded = bin;
    while (padded.size() % 4) padded += '\0';
    auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const uint32_t total = uint32_t(12 + 8 + text.size() + 8 + padded.size());
    return "glTF" + u32(2) + u32(total) + u32(uint32_t(text.size())) + "JSON" + text + u32(uint32_t(padded.size())) +
           std::string("BIN\0", 4) + padded;
}

}  // namespace glint_test
