#pragma once
/// \file What assimp gets to see of a glTF file: its geometry only, validated. Internal.

#include "gltf_document.h"
#include "mesh_file.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::gltf {

/// The geometry of `doc` as a self-contained GLB for assimp: scenes, nodes (names,
/// transforms, children, meshes), meshes (attributes, indices, mode), accessors and one
/// merged buffer; no materials, images, cameras, lights, skins, animations, morph targets or
/// extensions. Every accessor a primitive uses is checked to lie inside its buffer first, and
/// out-of-range index values are reported in `warnings`. Throws SceneError.
///
/// Why the document is written out again rather than handed to assimp (checked against
/// assimp 5.2.5's Importer.hpp and MemoryIOWrapper.h):
/// - assimp takes bytes only (ReadFile, or ReadFileFromMemory with an optional IOSystem for
///   the files the bytes name); there is no entry point for an already parsed document.
/// - The original bytes are not safe to give it: a node cycle or second parent makes it
///   recurse forever or read past its node array, an accessor outside its buffer makes it
///   read past the buffer, and a skin without inverseBindMatrices crashes it. Removing those
///   means changing the JSON, so it has to be serialised again anyway; leaving out what
///   Glint reads itself (materials, images...) also spares assimp decoding it.
/// - One embedded BIN chunk of the buffers already read and checked: assimp opens no file
///   (no second read of a .bin, no data URI decoded twice) and sees exactly the checked bytes.
[[nodiscard]] std::string geometry_glb(const Document& doc, std::vector<std::string>& warnings);

/// Per mesh primitive in assimp's numbering (mesh by mesh, primitive by primitive), its
/// material index (the count of materials for "none").
[[nodiscard]] std::vector<uint32_t> primitive_materials(const Document& doc);

/// The node-from-instance matrices (T·R·S) of `node`'s EXT_mesh_gpu_instancing instances;
/// empty for a node without the extension. Throws SceneError for an accessor outside its buffer.
[[nodiscard]] std::vector<Matrix4> gpu_instances(const Document& doc, const nlohmann::json& node);

/// EXT_mesh_gpu_instancing, which assimp 5.2.5 drops: each instanced node's placement in
/// `file` becomes one placement per instance. Returns the number of instances placed.
std::size_t expand_gpu_instancing(const Document& doc, MeshFile& file);

}  // namespace glint::gltf
