#pragma once
/// \file Names in a warning line: a few quoted, the rest counted. Internal.

#include <algorithm>
#include <string>
#include <vector>

namespace glint {

/// How many names a warning line lists before "and N more": enough to find the culprits,
/// few enough that a file with a hundred of them still gives a readable line.
inline constexpr std::size_t kListedNames = 4;

/// "'a', 'b', 'c', 'd' and 3 more": the first kListedNames of `names`, out of `total`
/// (which may exceed names.size() when only the first names were kept).
[[nodiscard]] inline std::string quoted_names(const std::vector<std::string>& names, std::size_t total) {
    std::string joined;
    const std::size_t listed = std::min(names.size(), kListedNames);
    for (std::size_t i = 0; i < listed; ++i) joined += (i ? ", '" : "'") + names[i] + "'";
    if (total > listed) joined += " and " + std::to_string(total - listed) + " more";
    return joined;
}

}  // namespace glint
