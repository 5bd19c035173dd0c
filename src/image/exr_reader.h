#pragma once
/// \file OpenEXR files read through OpenEXR alone, in the module that writes them
/// (`libglint_exr.so`, exr_codec.cpp). Internal to src/image.
///
/// Renders are read back as EXR (`glint assemble`, environment maps and textures a user
/// exports from Blender), and reading one through OpenImageIO first loads its 255 libraries,
/// 350-400 ms (docs/performance.md, "EXR input without OpenImageIO"). OpenImageIO 2.4 reads
/// EXR through the same OpenEXR, into the same floats; this reader orders the channels as it
/// does (by layer; R G B Y A Z and their kin first, X Y Z together in a layer that holds
/// them), marks alpha and the data window as it does and keeps the "glint:" attributes, so
/// that its result is OpenImageIO's bit for bit (ExrReader.* compares them). Multi-part and
/// deep files, integer and subsampled channels, cube maps, and any file OpenEXR throws on
/// are left to OpenImageIO, which reads them, or words their error,
/// as before.

#include "image_codec.h"

#include <cstddef>
#include <optional>
#include <string>

namespace glint::codec {

/// Whether `bytes` begin with OpenEXR's magic number (76 2f 31 01).
[[nodiscard]] inline bool is_exr(const unsigned char* bytes, std::size_t size) {
    return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

/// Decode the EXR in `bytes` into `out` as OpenImageIO would, decompressing on `threads`
/// threads. Returns "" on success or `check`'s refusal of the header's size (checked before
/// OpenEXR allocates anything for the pixels); nothing when the file is one to read through
/// OpenImageIO instead.
[[nodiscard]] std::optional<std::string> read_exr(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                                  int threads, DecodedImage& out);

}  // namespace glint::codec
