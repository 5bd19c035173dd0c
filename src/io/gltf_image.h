#pragma once
/// \file Decoding images held in memory (textures inside GLB, FBX or data URIs). Internal.

#include "glint/image/image.h"
#include "glint/image/image_io.h"

#include <string>
#include <vector>

namespace glint {

/// Decode PNG/JPEG/... bytes with OpenImageIO, applying the same sRGB rule as read_image().
/// `name` only tells the decoder which format to try first and names the image in errors.
/// Throws ImageError.
[[nodiscard]] Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name,
                                 ColorEncoding encoding = ColorEncoding::Color);

}  // namespace glint
