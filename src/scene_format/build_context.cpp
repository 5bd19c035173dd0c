#include "glint/scene_format/build_context.h"

#include "glint/scene/scene.h"
#include "glint/scene_format/did_you_mean.h"

#include <fmt/format.h>

namespace glint {

namespace {

template <class Map>
std::vector<std::string> keys_of(const Map& map) {
    std::vector<std::string> keys;
    for (const auto& entry : map) keys.push_back(entry.first);
    return keys;
}

}  // namespace

std::filesystem::path BuildContext::input_file(const ParamTable& table, std::string_view key) const {
    const ParamValue& v = table.require(key, "a file name, relative to the scene file's folder");
    const std::string& written = v.as_string(ValueName(table, key));
    if (const auto it = found_files_.find(written); it != found_files_.end()) return it->second;
    const std::filesystem::path name = written;
    const std::filesystem::path path = name.is_absolute() ? name : base_dir_ / name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        v.fail(ValueName(table, key), fmt::format("an existing file (looked for {})", path.string()));
    found_files_.emplace(written, path);
    return path;
}

std::shared_ptr<const Image> BuildContext::image(const ParamTable& table, std::string_view key,
                                                 ColorEncoding encoding) {
    const std::filesystem::path path = input_file(table, key);
    const std::string cache_key = path.string() + (encoding == ColorEncoding::Data ? "#data" : "#color");
    if (auto it = images_.find(cache_key); it != images_.end()) return it->second;
    try {
        auto image = std::make_shared<const Image>(read_image(path, encoding));
        images_.emplace(cache_key, image);
        return image;
    } catch (const ImageError& e) {
        table.fail(key, fmt::format("a readable image ({})", e.what()));
    }
}

const Texture* BuildContext::texture(const ParamTable& table, std::string_view key) const {
    const ParamValue* v = table.find(key);
    if (!v) return nullptr;
    const std::string& name = v->as_string(table.name_of(key));
    if (auto it = textures_.find(name); it != textures_.end()) return it->second;
    v->fail(table.name_of(key), "the name of a texture in [[textures]]" + did_you_mean(name, keys_of(textures_)));
}

uint32_t BuildContext::material(const ParamValue& value, const ValueName& what) const {
    const std::string& name = value.as_string(what);
    if (const auto index = scene_.find_material(name)) return *index;
    std::vector<std::string> names;
    for (const Material& m : scene_.materials()) names.push_back(m.name);
    value.fail(what, "the name of a material in [[materials]]" + did_you_mean(name, names));
}

}  // namespace glint
