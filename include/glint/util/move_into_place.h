#pragma once
/// \file The last step of writing a file safely: rename a finished temporary file onto its
/// final name (atomic within one file system), or remove it. A reader sees the old file or
/// the whole new one, never a part.

#include <filesystem>
#include <string>
#include <system_error>

namespace glint {

/// Rename `tmp` to `path`. On failure `tmp` is removed and the reason returned (empty on
/// success), for the caller to throw its own kind of error with.
[[nodiscard]] inline std::string move_into_place(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (!ec) return {};
    const std::string reason = ec.message();
    std::filesystem::remove(tmp, ec);
    return reason;
}

}  // namespace glint
