#pragma once
/// \file Random access to an image's bytes, for the header checks that run before
/// OpenImageIO or libpng sees them. Internal to src/image.

#include <cstddef>
#include <cstdint>
#include <functional>

namespace glint {

/// Reads `size` bytes at `offset` of the image into `out`; false when they are not there.
/// One reader serves a file on disk and an image held in memory (embedded in a GLB).
using ByteRangeReader = std::function<bool(uint64_t offset, unsigned char* out, std::size_t size)>;

}  // namespace glint
