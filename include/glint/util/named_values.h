#pragma once
/// \file What a render is made of, in words: (name, value) pairs that a checkpoint, an EXR
/// written by a crop, and each MPI rank carry, so that parts of different renders are never
/// joined. One comparison and one byte form serve all three.

#include "glint/util/byte_stream.h"

#include <string>
#include <utility>
#include <vector>

namespace glint {

using NamedValues = std::vector<std::pair<std::string, std::string>>;

/// One name whose values differ; a name one side lacks has the value "nothing" there.
struct NamedValueDifference {
    std::string name;
    std::string first;
    std::string second;
};

/// Every name whose values differ between `first` and `second`, in the order the names first
/// appear (`first`'s, then those only `second` has).
[[nodiscard]] std::vector<NamedValueDifference> named_value_differences(const NamedValues& first,
                                                                        const NamedValues& second);

/// A 32-bit count, then each name and value as text.
void write_named_values(ByteWriter& w, const NamedValues& values);

/// What write_named_values wrote; more than `max_items` pairs is a ByteStreamError.
[[nodiscard]] NamedValues read_named_values(ByteReader& r, uint32_t max_items);

}  // namespace glint
