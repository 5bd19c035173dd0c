#pragma once
/// \file The line an error points at, with a caret under the column (tungsten's JSON errors).

#include <cstdint>
#include <string>
#include <string_view>

namespace glint {

/// Two lines for an error message, each starting with a newline:
///    12 | difuse = 0.5
///       | ^
/// Empty if `line` is not in `text`. `line` and `column` are 1-based; tabs before the
/// column are kept so that the caret lines up.
[[nodiscard]] std::string source_excerpt(std::string_view text, uint32_t line, uint32_t column);

}  // namespace glint
