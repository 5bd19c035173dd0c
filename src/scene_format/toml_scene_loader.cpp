// The only translation unit that includes toml++ (it is heavy to compile): it turns TOML
// text into a ParamTable tree and hands that to the scene builder.

#include "glint/scene_format/toml_scene_loader.h"

#include "glint/scene_format/param_table.h"
#include "glint/scene_format/source_excerpt.h"
#include "glint/scene_format/scene_builder.h"

// toml++ compiled here, header-only (src/CMakeLists.txt says why), with floats read by
// std::from_chars (exact, locale-free; GCC 12 has it) and without its writers.
#define TOML_HEADER_ONLY 1
#define TOML_FLOAT_CHARCONV 1
#define TOML_ENABLE_FORMATTERS 0
#include <toml++/toml.h>

#include <fstream>

namespace glint {

namespace {

using FileName = std::shared_ptr<const std::string>;

SourceLocation location(const toml::source_region& region, const FileName& file) {
    return {file, region.begin.line, region.begin.column};
}

std::shared_ptr<const ParamTable> convert_table(toml::table& table, const std::string& path, const FileName& file);

/// The ParamValue of `node`, which is named `path` in messages. Tables and arrays are
/// emptied as they are converted, so that a large scene is never held twice: the toml++
/// tree of 100,000 objects alone takes 240 MB.
ParamValue convert(toml::node& node, const std::string& path, const FileName& file) {
    const SourceLocation where = location(node.source(), file);
    switch (node.type()) {
        case toml::node_type::table:
            return {convert_table(*node.as_table(), path, file), where};
        case toml::node_type::array: {
            ParamValue::Array elements;
            toml::array& array = *node.as_array();
            elements.reserve(array.size());
            for (std::size_t i = 0; i < array.size(); ++i) {
                toml::node& element = array[i];
                // Numbers and strings need no name of their own (a ParamValue's reader is
                // given one); tables keep theirs (ParamTable::path), and a date is refused by it.
                const bool nested = element.is_table() || element.is_array();
                const bool named = nested || element.is_date() || element.is_time() || element.is_date_time();
                elements.push_back(convert(element, named ? path + "[" + std::to_string(i) + "]" : path, file));
                if (nested) array.replace(array.cbegin() + std::ptrdiff_t(i), false);
            }
            array.clear();
            return {std::move(elements), where};
        }
        case toml::node_type::string:
            return {std::move(*node.as_string()).get(), where};
        case toml::node_type::integer:
            return {node.as_integer()->get(), where};
        case toml::node_type::floating_point:
            return {node.as_floating_point()->get(), where};
        case toml::node_type::boolean:
            return {node.as_boolean()->get(), where};
        default:
            throw_scene_error(where, path + " is a date or time; scene files use numbers, strings and arrays");
    }
}

std::shared_ptr<const ParamTable> convert_table(toml::table& table, const std::string& path, const FileName& file) {
    auto out = std::make_shared<ParamTable>(path, location(table.source(), file));
    out->reserve(table.size());
    for (auto& [key, node] : table) {
        const std::string name(key.str());
        out->add(name, location(key.source(), file), convert(node, path.empty() ? name : path + "." + name, file));
    }
    table.clear();
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
    // Read into one string of the file's size (a stringstream would hold it twice).
    std::string text(std::filesystem::file_size(path, ec), '\0');
    if (ec || !in.read(text.data(), std::streamsize(text.size())) || in.peek() != std::ifstream::traits_type::eof())
        throw SceneError(path.string() + ": cannot read the scene file");
    return load_toml_scene_string(text, path.string(), path.parent_path());
}

}  // namespace glint
