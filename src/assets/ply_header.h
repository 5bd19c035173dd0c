#pragma once
/// \file Glint's own reading of a PLY header, before assimp sees the file.
/// Internal to src/assets.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

namespace glint {

/// A PLY scalar type (PLY 1.0 names and their sized aliases: char/int8 ... double/float64).
enum class PlyScalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// The scalar type a header names, or nothing for an unknown name.
[[nodiscard]] std::optional<PlyScalar> ply_scalar_named(std::string_view name);
/// Bytes of one binary value of `type`.
[[nodiscard]] std::size_t ply_scalar_size(PlyScalar type);

/// Refuse, with a SceneError naming `path` (and the header line where there is one), a PLY
/// file whose header assimp would mishandle; files that are not PLY pass.
///
/// assimp 5.2.5 loops forever on a PLY header without `end_header`, and allocates for the
/// element counts a header declares before it reads the data (a 200-byte ASCII file that
/// declares 10⁹ vertices took 6 GB in 10 s). So a PLY file's header must end, and the data
/// after it must be long enough for the declared counts: at least one byte per binary
/// scalar or list length, two characters (a digit and a separator) per ASCII value. A
/// property of an unknown type is refused too: assimp skips nothing for it and reads a
/// declared 10⁹ vertices of nothing for minutes (found by fuzz/fuzz_ply).
void check_ply_header(const std::filesystem::path& path);

}  // namespace glint
