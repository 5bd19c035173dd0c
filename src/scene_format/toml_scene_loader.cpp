// The only translation unit that includes toml++ (it is heavy to compile): it turns TOML
// text into a ParamTable tree and hands that to the scene builder.

#include "glint/scene_format/toml_scene_loader.h"

#include "glint/scene_format/param_table.h"
#include "scene_builder.h"
#include "glint/scene_format/source_excerpt.h"

#include <toml++/toml.h>

#include <fstream>
#include <sstream>

namespace glint {

namespace {

using FileName = std::shared_ptr<const std::string>;

SourceLocation location(const toml::source_region& region, const FileName& file) {
    return {file, region.begin.line, region.begin.column};
}

std::shared_ptr<const ParamTable> convert_table(const toml::table& table, const std::string& path,
                                                const FileName& file);

ParamValue convert(const toml::node& node, const std::string& path, const FileName& file) {
    const SourceLocation where = location(node.source(), file);
    switch (node.type()) {
        case toml::node_type::table: return {convert_table(*node.as_table(), path, file), where};
        case toml::node_type::array: {
            ParamValue::Array elements;
            const toml::array& array = *node.as_array();
            for (std::size_t i = 0; i < array.size(); ++i)
                elements.push_back(convert(array[i], path + "[" + std::to_string(i) + "]", file));
            return {std::move(elements), where};
        }
        case toml::node_type::string: return {node.as_string()->get(), where};
        case toml::node_type::integer: return {node.as_integer()->get(), where};
        case toml::node_type::floating_point: return {node.as_floating_point()->get(), where};
        case toml::node_type::boolean: return {node.as_boolean()->get(), where};
        default: throw_scene_error(where, path + " is a date or time; scene files use numbers, strings and arrays");
    }
}

std::shared_ptr<const ParamTable> convert_table(const toml::table& table, const std::string& path,
                                                const FileName& file) {
    auto out = std::make_shared<ParamTable>(path, location(table.source(), file));
    for (const auto& [key, node] : table) {
        const std::string name(key.str());
        out->add(name, location(key.source(), file), convert(node, path.empty() ? name : path + "." + name, file));
    }
    return out;
}

}  // namespace

LoadedScene load_toml_scene_string(std::string_view text, const std::string& source_name,
                                   const std::filesystem::path& base_dir) {
    const auto file = std::make_shared<const std::string>(source_name);
    toml::table document;
    try {
        document = toml::parse(text, source_name);
    } catch (const toml::parse_error& e) {
        const SourceLocation where = location(e.source(), file);
        throw SceneError(where.to_string() + ": invalid TOML: " + std::string(e.description()) +
                         source_excerpt(text, where.line, where.column));
    }
    try {
        const auto root = convert_table(document, "", file);
        return build_scene(*root, base_dir);
    } catch (const LocatedSceneError& e) {
        if (!e.where().file || *e.where().file != source_name) throw;
        throw SceneError(e.what() + source_excerpt(text, e.where().line, e.where().column));
    }
}

LoadedScene load_toml_scene(const std::filesystem::path& path) {
    std::error_code ec;
    // A directory opens as an empty stream on Linux; it must not load as an empty scene.
    if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(path.string() + ": no such scene file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path.string() + ": cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();
    return load_toml_scene_string(text.str(), path.string(), path.parent_path());
}

}  // namespace glint
