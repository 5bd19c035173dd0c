#pragma once
/// \file What an import mapped and what it ignored, one line per kind. Internal.

#include "name_list.h"

#include <map>
#include <string>
#include <vector>

namespace glint {

/// Collects ignored features by kind so that a file with a hundred normal-mapped materials
/// gives one warning line, not a hundred.
class ImportNotes {
public:
    /// Something mapped, for `glint info`.
    void mapped(std::string line) { mapped_.push_back(std::move(line)); }
    /// `what` (the feature and why it is dropped) seen at `where` (a material or node name).
    void ignored(const std::string& what, const std::string& where) {
        auto [it, inserted] = ignored_.try_emplace(what);
        if (inserted) order_.push_back(what);
        if (!where.empty() && it->second.size() < kListedNames) it->second.push_back(where);
        ++counts_[what];
    }
    /// True if `what` was reported as ignored.
    [[nodiscard]] bool has(const std::string& what) const { return ignored_.count(what) > 0; }
    [[nodiscard]] const std::vector<std::string>& mapped_lines() const { return mapped_; }
    /// One line per kind: "what (on 'a', 'b' and 3 more)".
    [[nodiscard]] std::vector<std::string> ignored_lines() const {
        std::vector<std::string> lines;
        for (const std::string& what : order_) {
            const auto& where = ignored_.at(what);
            std::string line = what;
            if (!where.empty()) line += " (on " + quoted_names(where, counts_.at(what)) + ")";
            lines.push_back(std::move(line));
        }
        return lines;
    }

private:
    std::vector<std::string> mapped_;
    std::vector<std::string> order_;
    std::map<std::string, std::vector<std::string>> ignored_;
    std::map<std::string, std::size_t> counts_;
};

}  // namespace glint
