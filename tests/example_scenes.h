#pragma once
// The example scenes every end-to-end test walks: scenes/*.toml by name, sorted.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace glint_test {

/// The stems of scenes/*.toml under `source_dir`, sorted.
inline std::vector<std::string> example_scene_names(const std::filesystem::path& source_dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(source_dir / "scenes"))
        if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace glint_test
