#pragma once
/// \file "Did you mean ...?" suggestions for misspelt keys and names.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint {

/// Optimal-string-alignment distance between `a` and `b`, ignoring ASCII case: insertions,
/// deletions, substitutions and swaps of two adjacent characters each cost 1, so the
/// common typos `raduis` and `radis` are both one edit from `radius`.
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word`, if it is close enough to be the likely intent: at most
/// one edit for words of up to 4 characters, two up to 8, three beyond. Ties go to the
/// first candidate.
[[nodiscard]] std::optional<std::string> closest_match(std::string_view word, std::span<const std::string> candidates);

/// " (did you mean 'x'?)" for the closest candidate, or an empty string if none is close.
[[nodiscard]] std::string did_you_mean(std::string_view word, std::span<const std::string> candidates);

}  // namespace glint
