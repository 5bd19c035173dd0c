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
/// extensions. Why: Glint reads those itself from the JSON, and assimp 5.2.5 crashes on some
/// valid files in exactly those parts (a skin without inverseBindMatrices). Every accessor a
/// primitive uses is checked to lie inside its buffer first, and out-of-range index values
/// are reported in `warnings`. Throws SceneError.
[[nodiscard]] std::string geometry_glb(const Document& doc, std::vector<std::string>& warnings);

/// Per mesh primitive in assimp's numbering (mesh by mesh, primitive by primitive), its
/// material index (the count of materials for "none").
[[nodiscard]] std::vector<uint32_t> primitive_materials(const Document& doc);

/// EXT_mesh_gpu_instancing, which assimp 5.2.5 drops: each instanced node's placement in
/// `file` becomes one placement per instance. Returns the number of instances placed.
std::size_t expand_gpu_instancing(const Document& doc, MeshFile& file);

}  // namespace glint::gltf
