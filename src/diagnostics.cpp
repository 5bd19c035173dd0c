#include "glint/diagnostics.h"

#include <fmt/format.h>

namespace glint {

std::string SourceLocation::to_string() const {
    const std::string name = file ? *file : std::string("<scene>");
    if (line == 0) return name;
    return column == 0 ? fmt::format("{}:{}", name, line) : fmt::format("{}:{}:{}", name, line, column);
}

void throw_scene_error(const SourceLocation& where, const std::string& message) {
    throw LocatedSceneError(where, message);
}

}  // namespace glint
