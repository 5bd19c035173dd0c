#pragma once
/// \file assimp, kept at arm's length. assimp 5.2.5 (Debian 12) aborts or crashes on some
/// malformed files: an ai_assert in its triangulation aborts on a PLY with NaN positions; its
/// MTL reader dereferences a null material when `map_Kd` comes before any `newmtl` (found
/// by fuzz/fuzz_ply and fuzz/fuzz_obj_mtl). So every import is first run in a forked child
/// process. A child that crashes becomes a SceneError naming the file; a child that reads
/// and frees the scene (or gets assimp's error) shows that the same import is safe in this
/// process, since assimp reads the same bytes the same way. The limit: an overrun that
/// damages nothing glibc checks passes in both processes (a sanitizer build sees it); to
/// hand the child's scene over instead would close that, but assimp's own binary format
/// (assbin) drops mesh names and morph targets and narrows indices to 16 bits.
///
/// Forking is safe here because scenes load before the renderer starts worker threads and
/// glibc's malloc prepares for fork; an allocator that does not (clang 14's ASan) needs a
/// single-threaded caller, which is why fuzz/fuzz_harness.cpp keeps TBB to one thread.
///
/// Internal to src/assets.

#include <assimp/Importer.hpp>

#include <functional>
#include <string>

namespace glint {

/// Run `import` on a fresh Importer in a child process and wait for it. Throws SceneError
/// "`context`: assimp crashed on this file (signal): first line it printed; ..." when the
/// child dies; returns when it ends normally.
void probe_import(const std::function<void(Assimp::Importer&)>& import, const std::string& context);

}  // namespace glint
