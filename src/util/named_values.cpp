#include "glint/util/named_values.h"

#include <algorithm>

namespace glint {

namespace {

const std::string& value_of(const NamedValues& values, const std::string& name) {
    static const std::string nothing = "nothing";
    const auto it = std::find_if(values.begin(), values.end(), [&](const auto& item) { return item.first == name; });
    return it == values.end() ? nothing : it->second;
}

}  // namespace

std::vector<NamedValueDifference> named_value_differences(const NamedValues& first, const NamedValues& second) {
    std::vector<std::string> names;
    for (const NamedValues* values : {&first, &second})
        for (const auto& [name, value] : *values)
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    std::vector<NamedValueDifference> differences;
    for (const std::string& name : names)
        if (const std::string& a = value_of(first, name), &b = value_of(second, name); a != b)
            differences.push_back({name, a, b});
    return differences;
}

void write_named_values(ByteWriter& w, const NamedValues& values) {
    w.u32(uint32_t(values.size()));
    for (const auto& [name, value] : values) {
        w.text(name);
        w.text(value);
    }
}

NamedValues read_named_values(ByteReader& r, uint32_t max_items) {
    const uint32_t items = r.u32();
    if (items > max_items) throw ByteStreamError("more named values than a record can hold");
    NamedValues values(items);
    for (auto& [name, value] : values) {
        name = r.text();
        value = r.text();
    }
    return values;
}

}  // namespace glint
