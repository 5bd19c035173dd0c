#pragma once
/// \file Reading and writing images through OpenImageIO.

#include "glint/image/image.h"
#include "glint/image/tone_curve.h"

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace glint {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// How the stored values of an image file relate to linear light.
enum class ColorEncoding {
    /// Colour data: 8/16-bit integer files are sRGB-encoded and decoded to linear;
    /// float files (EXR, HDR, PFM) are already linear.
    Color,
    /// Non-colour data (alpha, roughness, heights): read the values as they are.
    Data,
};

/// Most values (pixels × channels) an image read as a texture or environment may hold:
/// 2 GiB of floats, a 16384×8192 RGBA image (a "16K" HDR environment)...
inline constexpr std::size_t kMaxImageValues = std::size_t(1) << 29;
/// ...and its longest side, that of a 64K panorama.
inline constexpr int kMaxImageSide = 65536;

/// Read any format OpenImageIO knows into linear floats. Throws ImageError naming the file,
/// also for an image of more than kMaxImageValues values.
[[nodiscard]] Image read_image(const std::filesystem::path& path, ColorEncoding encoding = ColorEncoding::Color);

/// Decode PNG/JPEG/... bytes held in memory (textures inside GLB or FBX files) with the same
/// rules as read_image(). `name` tells the decoder which format to try first and names the
/// image in errors. Throws ImageError.
[[nodiscard]] Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name,
                                 ColorEncoding encoding = ColorEncoding::Color);

/// The display transform for display formats (PNG, JPEG, 8-bit TIFF): value·2^exposure, then
/// the tone curve, then sRGB encoding. Float formats ignore both.
struct WriteOptions {
    /// Stops (an automatic exposure is resolved by the caller: auto_exposure_stops).
    float exposure = 0.0f;
    ToneCurve tone_curve = ToneCurve::None;
};

/// Write by extension: .exr, .hdr, .pfm keep linear floats; .png, .jpg, .tif, .bmp get
/// the display transform of `options` and sRGB encoding in 8 bits. An EXR keeps every channel
/// of an image whose channels are named (Image::channel_names: a partial render's "samples",
/// AOVs), its region in a frame as its data window, and its attributes; the other formats
/// write R, G, B of the pixels alone. The file is written under a temporary name in the same
/// folder and renamed, so a failure never leaves a partial image. Throws ImageError.
void write_image(const std::filesystem::path& path, const Image& image, const WriteOptions& options = {});

/// The temporary name write_image writes `path` under before renaming it into place:
/// hidden, beside it, and unique to this process.
[[nodiscard]] std::filesystem::path temporary_path_for(const std::filesystem::path& path);

/// True if write_image writes `path` as linear floats (.exr, .hdr, .pfm), which no display
/// transform touches.
[[nodiscard]] bool keeps_radiance(const std::filesystem::path& path);

/// True if write_image knows the extension of `path`.
[[nodiscard]] bool is_supported_output(const std::filesystem::path& path);

/// Throw ImageError, saying what is wrong, unless write_image could put an image at `path`:
/// a known extension, not a folder, in an existing folder this process may write to.
/// Programs call it before a long render so that a bad name fails at once.
void check_output_path(const std::filesystem::path& path);

}  // namespace glint
