#pragma once
/// \file Glint's own reader for the PLY files most users have: binary triangle meshes such
/// as the Stanford scans. Internal to src/assets.
///
/// assimp reads every PLY file, but through the import child (isolated_import.h) and its
/// own scene structures: 0.16 s for the 202,520-triangle dragon and 0.60 s for the full
/// 871,414-triangle one, where reading the bytes takes milliseconds. This reader takes the
/// files whose meaning is plain and hands everything else to assimp, so that a file reads
/// the same whichever reader takes it (tests/ply_triangles_test.cpp compares the two).

#include "mesh_file.h"

#include <filesystem>
#include <optional>

namespace glint {

/// `path` as assimp would read it in `mode`, when it is a plain triangle mesh: a binary
/// PLY (either byte order) with exactly the elements `vertex` (scalar properties x, y, z
/// and optionally nx, ny, nz, each float or double) and `face` (one list property
/// vertex_indices or vertex_index of integers, three per face), at least one of each,
/// finite positions, indices below the vertex count, and nothing after the faces.
/// Nothing for any other file, which assimp then reads (and words its errors for).
[[nodiscard]] std::optional<MeshFile> read_plain_ply(const std::filesystem::path& path, ReadMode mode);

}  // namespace glint
