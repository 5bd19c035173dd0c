#pragma once
/// \file assimp, kept out of Glint's process. assimp 5.2.5 (Debian 12) aborts, crashes or
/// writes out of bounds on some malformed files: an ai_assert in its triangulation aborts on
/// a PLY with NaN positions; its MTL reader dereferences a null material when `map_Kd` comes
/// before any `newmtl`; its PLY reader overruns buffers that an uninstrumented library
/// leaves unreported, and the damage showed up later as crashes in unrelated code (found by
/// fuzz/fuzz_ply and fuzz/fuzz_obj_mtl). So every import runs, with the conversion to
/// Glint's meshes, in a forked child process that hands back flat bytes
/// (mesh_file_bytes.h); assimp never touches this process's memory. A child that crashes
/// becomes a SceneError naming the file; the bytes it hands back are checked as they are
/// read, like any file.
///
/// Forking is safe here because scenes load before the renderer starts worker threads and
/// glibc's malloc prepares for fork; an allocator that does not (clang 14's ASan) needs a
/// single-threaded caller, which is why fuzz/fuzz_harness.cpp keeps TBB to one thread.
///
/// Internal to src/assets.

#include <functional>
#include <string>
#include <vector>

namespace glint {

/// Run `work` in a child process and return the bytes it returned. What `work` throws comes
/// back as a SceneError with the same message (prefixed by "`context`: " unless it is a
/// SceneError, which names its file already). A child that dies throws SceneError
/// "`context`: assimp crashed on this file (signal): first line it printed; ...".
[[nodiscard]] std::vector<char> run_isolated(const std::function<std::string()>& work, const std::string& context);

}  // namespace glint
