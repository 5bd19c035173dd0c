#pragma once
/// \file The entries of one top-level array of tables (`[[objects]]`) in TOML text, found by
/// reading its lines, not by parsing it: so that a scene of 100,000 objects is parsed and
/// built one object at a time instead of holding toml++'s tree of all of them (236 MB for
/// 100,000 objects; docs/performance.md).
///
/// This reads only as much TOML as it takes to tell a table header from a line inside a
/// value: comments, the four kinds of strings (two of which may span lines) and the
/// brackets of arrays that span lines. It does not check the text: whatever it mistakes
/// fails to parse on one side or the other, and the loader then parses the file whole
/// (toml_scene_loader.cpp), so it can cost time but never change what a file means.
///
/// Internal to src/scene_format.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

/// One `[[name]]` entry: its header line and every line up to the next header that is not
/// its own (`[name.sub]`, `[[name.sub]]`), in whole lines.
struct TomlEntry {
    std::string_view text;
    uint32_t first_line = 1;  ///< of `text` in the whole file, counting from 1
};

struct TomlEntries {
    /// The text without the entries, each replaced by as many line breaks as it had lines,
    /// so that every other line keeps its number and its columns.
    std::string rest;
    /// In file order; views into the text that was split.
    std::vector<TomlEntry> entries;
};

/// Take the entries of the top-level array of tables `name` out of `text`.
[[nodiscard]] TomlEntries split_toml_entries(std::string_view text, std::string_view name);

}  // namespace glint
