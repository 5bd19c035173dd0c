#include "toml_entries.h"

namespace glint {

namespace {

/// What is open at the end of a line: TOML's multi-line strings (`"""`, `'''`) and the
/// brackets and braces of a value that goes on.
struct OpenAtLineEnd {
    char multiline_quote = 0;  ///< '"' or '\'' inside a multi-line string, else 0
    int brackets = 0;

    [[nodiscard]] bool nothing() const { return multiline_quote == 0 && brackets == 0; }
};

std::string_view trim_front(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

bool three(std::string_view line, std::size_t at, char quote) {
    return line.size() >= at + 3 && line[at] == quote && line[at + 1] == quote && line[at + 2] == quote;
}

/// The position after the closing quotes of a multi-line string at `at`, or npos if it
/// does not close on this line. Up to two more quotes after the three belong to the
/// string (TOML 1.0: `""""` ends it with a quote).
std::size_t close_multiline(std::string_view line, std::size_t at, char quote) {
    while (at < line.size()) {
        if (quote == '"' && line[at] == '\\') {
            at += 2;  // an escape; a backslash at the end of the line trims the line break
        } else if (three(line, at, quote)) {
            at += 3;
            for (int extra = 0; extra < 2 && at < line.size() && line[at] == quote; ++extra) ++at;
            return at;
        } else {
            ++at;
        }
    }
    return std::string_view::npos;
}

/// Follow a line of keys and values (not a header), updating what is open at its end.
void follow_values(std::string_view line, OpenAtLineEnd& open) {
    std::size_t at = 0;
    if (open.multiline_quote != 0) {
        at = close_multiline(line, 0, open.multiline_quote);
        if (at == std::string_view::npos) return;
        open.multiline_quote = 0;
    }
    while (at < line.size()) {
        const char c = line[at];
        if (c == '#') return;
        if (c == '"' || c == '\'') {
            if (three(line, at, c)) {
                at = close_multiline(line, at + 3, c);
                if (at == std::string_view::npos) {
                    open.multiline_quote = c;
                    return;
                }
                continue;
            }
            for (++at; at < line.size() && line[at] != c; ++at)
                if (c == '"' && line[at] == '\\') ++at;
            ++at;
            continue;
        }
        if (c == '[' || c == '{') ++open.brackets;
        if ((c == ']' || c == '}') && open.brackets > 0) --open.brackets;
        ++at;
    }
}

enum class Header { none, entry, inside_entry, other };

/// What a line outside any value is: `[[name]]`, a header below it (`[name.x]`,
/// `[[name.x]]`), another header, or not a header. Quoted keys ("name") count as other.
Header classify(std::string_view line, std::string_view name) {
    line = trim_front(line);
    if (line.empty() || line.front() != '[') return Header::none;
    const bool array = line.size() > 1 && line[1] == '[';
    std::string_view key = trim_front(line.substr(array ? 2 : 1));
    if (!key.starts_with(name)) return Header::other;
    key = trim_front(key.substr(name.size()));
    if (key.starts_with('.')) return Header::inside_entry;
    return array && key.starts_with("]]") ? Header::entry : Header::other;
}

}  // namespace

TomlEntries split_toml_entries(std::string_view text, std::string_view name) {
    TomlEntries out;
    OpenAtLineEnd open;
    bool in_entry = false;
    std::size_t entry_start = 0;
    uint32_t line_number = 1;
    const auto end_entry = [&](std::size_t at) {
        if (in_entry) out.entries.back().text = text.substr(entry_start, at - entry_start);
        in_entry = false;
    };
    for (std::size_t at = 0; at < text.size(); ++line_number) {
        const std::size_t newline = text.find('\n', at);
        const std::size_t next = newline == std::string_view::npos ? text.size() : newline + 1;
        const std::string_view line = text.substr(at, next - at);
        const Header header = open.nothing() ? classify(line, name) : Header::none;
        if (header == Header::entry || header == Header::other) end_entry(at);
        if (header == Header::entry) {
            in_entry = true;
            entry_start = at;
            out.entries.push_back({{}, line_number});
        }
        if (header == Header::none) follow_values(line.substr(0, line.find_last_not_of("\r\n") + 1), open);
        if (!in_entry)
            out.rest.append(line);
        else if (newline != std::string_view::npos)
            out.rest.push_back('\n');
        at = next;
    }
    end_entry(text.size());
    return out;
}

}  // namespace glint
