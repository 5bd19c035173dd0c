#pragma once
// Small textured glTF files written by tests: the quad of gltf_test_files.h with texture
// coordinates and one-row PNG textures.

#include "gltf_test_files.h"
#include "png_file.h"

#include <gtest/gtest.h>


#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace glint_test {

/// One 8-bit RGB texel.
using Texel = std::array<unsigned char, 3>;

/// Write `texels` (left to right, one row) as an 8-bit RGB PNG; returns the file's bytes. The
/// bytes go to the file as they are, with no colour conversion on the way.
inline std::string write_png(const std::filesystem::path& path, const std::vector<Texel>& texels) {
    std::vector<unsigned char> samples;
    for (const Texel& t : texels) samples.insert(samples.end(), t.begin(), t.end());
    return write_png8(path, int(texels.size()), 1, 3, samples);
}

/// The test quad with `material` as its only material and one texture per file in `images`
/// (texture i shows image i). Its texture coordinates reuse the positions' bytes: these
/// tests look textures up at chosen coordinates, or render uniform ones.
inline nlohmann::json quad_json_with(const nlohmann::json& material, const std::vector<std::string>& images) {
    nlohmann::json j = quad_json("quad.bin");
    j["accessors"].push_back({{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
    j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
    j["images"] = nlohmann::json::array();
    j["textures"] = nlohmann::json::array();
    for (std::size_t i = 0; i < images.size(); ++i) {
        j["images"].push_back({{"uri", images[i]}});
        j["textures"].push_back({{"source", i}});
    }
    j["materials"][0] = material;
    return j;
}

}  // namespace glint_test
