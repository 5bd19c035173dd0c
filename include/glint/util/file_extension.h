#pragma once
/// \file The extension of a file name in lower case, by which loaders and writers choose
/// a format (".EXR" and ".exr" are one format).

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace glint {

/// ".exr" for "Out.EXR"; empty when the name has no extension.
[[nodiscard]] inline std::string lower_case_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace glint
