#pragma once
/// \file The raw glTF 2.0 document: its JSON and its buffers, read without assimp.
///
/// Why a second reader next to assimp: assimp 5.2.5 turns glTF into its own scene graph and
/// drops what Glint needs to map the file faithfully (KHR_materials_ior, the extension lists,
/// which node holds which camera or light, image data it did not reference). The JSON is
/// small, so reading it with nlohmann-json costs little; the heavy part (accessors, vertex
/// data) stays with assimp. Internal to libglint.

#include "glint/math/transform.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace glint::gltf {

/// GLB container words (glTF 2.0 §4.4): the file's magic and the two chunk types, little-endian.
inline constexpr uint32_t kGlbMagic = 0x46546C67;     // "glTF"
inline constexpr uint32_t kChunkJson = 0x4E4F534A;    // "JSON"
inline constexpr uint32_t kChunkBinary = 0x004E4942;  // "BIN\0"

/// Throw SceneError "path: what": every glTF problem names the file first.
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what);

struct Document {
    std::filesystem::path path;
    nlohmann::json json;
    /// Bytes of each buffer (the GLB's BIN chunk, an external .bin or a data URI).
    std::vector<std::vector<unsigned char>> buffers;
    bool binary = false;
};

/// A node of the default scene with its world-from-node matrix.
struct PlacedNode {
    int node = 0;
    Matrix4 world_from_node;
    /// Index of its parent in the placed_nodes() list; -1 for a root.
    int parent = -1;
};

/// Read a .gltf or .glb and every buffer it references. Throws SceneError naming the file
/// and the problem (truncated GLB, bad JSON, missing or short .bin).
[[nodiscard]] Document read_document(const std::filesystem::path& path);

/// Every node reachable from the default scene (or from all root nodes when the file has
/// no scenes), in depth-first order, with its accumulated transform: of the nodes' own
/// (node_matrix), or of `local` (one matrix per node: the nodes posed by an animation).
[[nodiscard]] std::vector<PlacedNode> placed_nodes(const Document& doc, const std::vector<Matrix4>* local = nullptr);

/// A node's local transform (glTF 2.0 §3.5.3): its matrix, or T·R·S of its translation,
/// rotation and scale.
[[nodiscard]] Matrix4 node_matrix(const nlohmann::json& node);

/// The encoded bytes (PNG, JPEG...) of image `index` and a file name whose extension tells
/// the decoder the format. Throws SceneError when the image cannot be found.
[[nodiscard]] std::vector<unsigned char> image_bytes(const Document& doc, int index, std::string& name);

/// Whether bytes [offset, offset + length) lie inside `size` bytes (no wrap-around).
[[nodiscard]] bool fits_in(std::size_t offset, std::size_t length, std::size_t size);

/// Whether `count` elements of `element` bytes, `stride` apart (stride >= element >= 1),
/// starting at `offset`, lie inside `length` bytes (no wrap-around for hostile counts).
[[nodiscard]] bool elements_fit(std::size_t offset, std::size_t count, std::size_t stride, std::size_t element,
                                std::size_t length);

/// Most elements an accessor without a bufferView (all zeros) may have: its count is not
/// bounded by any data in the file.
inline constexpr std::size_t kMaxZeroAccessor = std::size_t(1) << 24;

/// Accessor `index` as `components` floats per element (FLOAT, or normalized integer types
/// mapped to [0, 1] / [-1, 1] as the spec says). Throws SceneError if it lies outside its buffer.
[[nodiscard]] std::vector<float> read_floats(const Document& doc, std::size_t index, int components);

/// Deepest nesting of JSON objects and arrays accepted; glTF itself needs about six levels,
/// and `extras` written by tools rarely more than a few.
inline constexpr int kMaxNesting = 64;

/// The matrix T·R·S of a translation, a unit quaternion (x, y, z, w) and a scale.
[[nodiscard]] Matrix4 trs_matrix(const Vec3& translation, const float rotation[4], const Vec3& scale);

/// `value` as a glTF integer property (an index, count, byte offset or enum). nlohmann's
/// get<>() converts a float with a plain cast, undefined for -4.383 to std::size_t (found by
/// fuzz/fuzz_gltf); this throws nlohmann::json::type_error, reported as "malformed glTF",
/// for anything but an integer within the range of `Integer`.
template <class Integer>
[[nodiscard]] Integer integer(const nlohmann::json& value) {
    if (value.is_number_unsigned()) {
        if (const auto u = value.get<std::uint64_t>(); std::in_range<Integer>(u)) return Integer(u);
    } else if (value.is_number_integer()) {
        if (const auto i = value.get<std::int64_t>(); std::in_range<Integer>(i)) return Integer(i);
    }
    const std::string expected = std::numeric_limits<Integer>::min() == 0
                                     ? "a non-negative integer"
                                     : "an integer from " + std::to_string(std::numeric_limits<Integer>::min()) +
                                           " to " + std::to_string(std::numeric_limits<Integer>::max());
    // A number is shown; anything else by its type, since it may be large or deeply nested.
    const std::string got = value.is_number() ? value.dump() : std::string(value.type_name());
    throw nlohmann::json::type_error::create(302, "expected " + expected + ", got " + got, &value);
}

/// An error's message, without the "[json.exception.type_error.302] " prefix of nlohmann's,
/// which names the library's internals rather than the file.
[[nodiscard]] std::string json_error_text(const std::exception& error);

/// `object[key]` as integer(), `fallback` when the key is absent.
template <class Integer>
[[nodiscard]] Integer integer_or(const nlohmann::json& object, const char* key, Integer fallback) {
    return object.contains(key) ? integer<Integer>(object[key]) : fallback;
}

/// Size of the array `key` at the top level (0 when absent).
[[nodiscard]] std::size_t array_size(const nlohmann::json& json, const char* key);

}  // namespace glint::gltf
