#pragma once
/// \file Glint's own reading of a PLY header, before assimp sees the file.
/// Internal to src/assets.

#include <filesystem>

namespace glint {

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
