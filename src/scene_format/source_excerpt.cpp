#include "glint/scene_format/source_excerpt.h"

#include <fmt/format.h>

namespace glint {

std::string source_excerpt(std::string_view text, uint32_t line, uint32_t column) {
    if (line == 0) return {};
    std::size_t begin = 0;
    for (uint32_t l = 1; l < line; ++l) {
        begin = text.find('\n', begin);
        if (begin == std::string_view::npos) return {};
        ++begin;
    }
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view source_line = text.substr(begin, end - begin);
    if (!source_line.empty() && source_line.back() == '\r') source_line.remove_suffix(1);

    std::string pad;
    for (std::size_t i = 0; i + 1 < column && i < source_line.size(); ++i) pad += source_line[i] == '\t' ? '\t' : ' ';
    const std::string number = std::to_string(line);
    return fmt::format("\n {} | {}\n {} | {}^", number, source_line, std::string(number.size(), ' '), pad);
}

}  // namespace glint
