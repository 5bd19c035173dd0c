#include "glint/io/scene_file.h"

#include "glint/io/toml_scene_loader.h"

#include <algorithm>
#include <cctype>

namespace glint {

LoadedScene load_scene_file(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".toml") return load_toml_scene(path);
    throw SceneError(path.string() + ": unknown scene format '" + ext + "' (expected a .toml scene)");
}

}  // namespace glint
