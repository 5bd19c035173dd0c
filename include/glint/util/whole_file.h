#pragma once
/// \file A file's bytes in one string of its size, read in one call: a scene file of tens of
/// megabytes is read once for parsing and once for a checkpoint's fingerprint.

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>

namespace glint {

/// The bytes of the regular file `path`, or nothing when it cannot be read whole (absent, a
/// folder, unreadable, or changing size while read). The caller words the error.
[[nodiscard]] inline std::optional<std::string> read_whole_file(const std::filesystem::path& path) {
    std::error_code ec;
    // A directory opens as an empty stream on Linux; it must not read as an empty file.
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::string bytes(std::filesystem::file_size(path, ec), '\0');
    if (!in || ec || !in.read(bytes.data(), std::streamsize(bytes.size())) ||
        in.peek() != std::ifstream::traits_type::eof())
        return std::nullopt;
    return bytes;
}

}  // namespace glint
