#pragma once
// The quad of gltf_test_files.h with glTF node animations: each channel's key times and
// values go into a second buffer, embedded as a data: URI.

#include "gltf_test_files.h"

#include <cstddef>
#include <string>
#include <vector>

namespace glint_test {

inline std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 2]));
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

class AnimatedQuad {
public:
    /// The quad as node 0 ("quad"), no animations yet.
    AnimatedQuad() : json_(quad_json("")) {}

    /// The document, to change nodes or add cameras before write().
    nlohmann::json& json() { return json_; }

    /// A FLOAT accessor of `type` ("SCALAR", "VEC3", "VEC4") holding `floats`; its index.
    std::size_t accessor(const std::vector<float>& floats, const std::string& type) {
        const std::size_t components = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : 4;
        const std::size_t view = json_["bufferViews"].size(), index = json_["accessors"].size();
        json_["bufferViews"].push_back(
            {{"buffer", 1}, {"byteOffset", bytes_.size()}, {"byteLength", floats.size() * sizeof(float)}});
        json_["accessors"].push_back(
            {{"bufferView", view}, {"componentType", 5126}, {"count", floats.size() / components}, {"type", type}});
        bytes_.append(reinterpret_cast<const char*>(floats.data()), floats.size() * sizeof(float));
        return index;
    }

    /// A sampler of animation 0 with these keys and a channel driving `path` of `node`.
    void channel(int node, const std::string& path, const std::vector<float>& times, const std::vector<float>& values,
                 const std::string& interpolation = "LINEAR") {
        if (!json_.contains("animations"))
            json_["animations"] = {{{"channels", nlohmann::json::array()}, {"samplers", nlohmann::json::array()}}};
        auto& animation = json_["animations"][0];
        const std::size_t sampler = animation["samplers"].size();
        const std::size_t input = accessor(times, "SCALAR");
        const std::size_t output = accessor(values, path == "rotation" ? "VEC4" : "VEC3");
        animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
        animation["channels"].push_back({{"sampler", sampler}, {"target", {{"node", node}, {"path", path}}}});
    }

    /// Write dir/name.gltf (and the quad's dir/name.bin).
    std::filesystem::path write(const std::filesystem::path& dir, const std::string& name) const {
        nlohmann::json json = json_;
        json["buffers"][1] = {{"uri", "data:application/octet-stream;base64," + base64(bytes_)},
                              {"byteLength", bytes_.size()}};
        return write_gltf(dir, name, json);
    }

private:
    nlohmann::json json_;
    std::string bytes_;
};

}  // namespace glint_test
