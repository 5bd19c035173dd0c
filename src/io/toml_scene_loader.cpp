#include "glint/io/toml_scene_loader.h"

namespace glint {

LoadedScene load_toml_scene(const std::filesystem::path& path) {
    throw SceneError(path.string() + ": TOML scenes are not implemented yet");
}

LoadedScene load_toml_scene_string(std::string_view, const std::string& source_name, const std::filesystem::path&) {
    throw SceneError(source_name + ": TOML scenes are not implemented yet");
}

}  // namespace glint
