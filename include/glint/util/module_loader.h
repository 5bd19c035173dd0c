#pragma once
/// \file Glint's modules: the parts whose libraries cost every process that links them more
/// than most runs need, built as shared objects that libglint loads on first use
/// (`libglint_oiio.so`, `libglint_exr.so`: src/image/image_codec.h; `libglint_assimp.so`:
/// src/assets/assimp_module.h). Each hands out a table of plain function pointers through
/// one entry point; no exception crosses the boundary.

#include <filesystem>
#include <string>

namespace glint {

/// The entry point `entry` (a function) of the module the build put at `built`, else of the
/// module of that name where `cmake --install` puts it (lib/glint/ under the prefix of the
/// running program, beside the program, or beside the shared object this code is linked
/// into: the Python module). Loaded once and never closed. Null when no candidate loads or
/// has the entry point; `reasons` then says why for each.
[[nodiscard]] void* load_module_entry(const std::filesystem::path& built, const char* entry, std::string& reasons);

/// The table the module at `built` hands out through `entry` (a `const Table* entry()`).
/// Throws `Error` ("cannot load Glint's `what` module (reasons)") when it cannot be loaded.
template <typename Table, typename Error>
const Table& load_module_table(const std::filesystem::path& built, const char* entry, const char* what) {
    std::string reasons;
    void* function = load_module_entry(built, entry, reasons);
    if (!function) throw Error(std::string("cannot load Glint's ") + what + " module (" + reasons + ")");
    return *reinterpret_cast<const Table* (*)()>(function)();
}

}  // namespace glint
