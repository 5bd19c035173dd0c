#pragma once
/// \file The boundary between libglint and its image libraries. Internal to src/image.
///
/// Debian's OpenImageIO brings 255 shared libraries (OpenCV with GStreamer and FFmpeg,
/// OpenVDB, DCMTK...), all bound at load time: linked into a program, they cost it 200 ms and
/// 130 MB before main() (docs/performance.md, "Start-up"). So OpenImageIO lives in a module of
/// its own, `libglint_oiio.so` (oiio_codec.cpp), which image_io.cpp loads the first time an
/// image is read or written: `glint --help`, `glint info`, a scene file's error and every
/// test that touches no image never pay for it. Even loaded on demand it costs the process
/// that reads or writes an image 350-400 ms (on a 2-core EPYC), more than a small render: so
/// EXR, the format renders are written in, is written and read by OpenEXR alone, in a second
/// module (`libglint_exr.so`, exr_codec.cpp and exr_reader.h: four libraries, 3 ms), PNG is
/// written by Glint itself over zlib (png_writer.h), and Radiance pictures, most environment
/// maps, and PNG and JPEG files, most textures, are read by Glint too (radiance_picture.h;
/// png_reader.h, through libpng; jpeg_reader.h, through libjpeg).
///
/// The modules hand out plain function pointers (no exceptions and no vtables cross the
/// boundary); each returns "" on success and otherwise what went wrong, worded to follow
/// "NAME: ".

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glint::codec {

/// An 8-bit sample as OpenImageIO converts it to float: the value times the reciprocal of
/// 255, in float. Dividing by 255 differs in the last bit for some values, so Glint's readers
/// (png_reader.h, jpeg_reader.h) and the sRGB table of image_io.cpp all convert through this.
[[nodiscard]] inline float float_of_byte(unsigned level) { return float(level) * (1.0f / 255.0f); }

/// An image as its file stores it, its values converted to floats (8-bit 255 → 1.0).
struct DecodedImage {
    int width = 0, height = 0, channels = 0;
    /// Handed on to the Image without a copy: a 2048×2048 RGB texture's floats are 50 MB.
    std::vector<float> pixels;
    std::vector<std::string> channel_names;
    /// Stored as integers (display-encoded colour unless tagged linear) rather than floats.
    bool integer_data = false;
    /// The file says its values are linear ("oiio:ColorSpace" Linear).
    bool linear_tagged = false;
    /// The channel the file marks as alpha (coverage), -1 for none.
    int alpha_channel = -1;
    /// The data window inside the display window (EXR); frame_width 0 when they are one.
    int x = 0, y = 0, frame_width = 0, frame_height = 0;
    /// The header's "glint:NAME" text attributes, as (NAME, text).
    std::vector<std::pair<std::string, std::string>> attributes;
};

/// Called with a header's size before any pixel is allocated or read: a message refuses the
/// image (a header may claim any size), "" accepts it.
using SizeCheck = std::function<std::string(int width, int height, int channels)>;

/// Float pixels to write: `channels` per pixel, row by row from the top.
struct PixelsToWrite {
    int width = 0, height = 0, channels = 0;
    const float* data = nullptr;
    /// Store floats (EXR, HDR) rather than 8-bit integers (the values are then display values).
    bool floats = false;
    /// Channel names to store (EXR AOVs); null for R, G, B.
    const std::vector<std::string>* channel_names = nullptr;
    /// A data window at (x, y) in a display window of frame_width × frame_height (EXR);
    /// frame_width 0: the pixels are the whole image.
    int x = 0, y = 0, frame_width = 0, frame_height = 0;
    /// Text attributes to store as "glint:NAME" (EXR); may be null.
    const std::vector<std::pair<std::string, std::string>>* attributes = nullptr;
    /// Threads the writer may compress with (EXR).
    int threads = 1;
};

/// Glint's own header attributes: "glint:scene", "glint:spp", ...
inline const std::string kAttributePrefix = "glint:";

struct Functions {
    /// Read the file at `path` (straight, unassociated alpha).
    std::string (*read_file)(const std::string& path, const SizeCheck& check, DecodedImage& out);
    /// Read `size` bytes in memory; `name`'s extension says which format to try first.
    std::string (*read_memory)(const unsigned char* bytes, std::size_t size, const std::string& name,
                               const SizeCheck& check, DecodedImage& out);
    /// Write `pixels` to `file` in the format `format_name`'s extension names.
    std::string (*write_file)(const std::string& format_name, const std::string& file, const PixelsToWrite& pixels);
};

/// The EXR module's functions.
struct ExrFunctions {
    /// Write `pixels` (floats) to `file` as OpenEXR.
    std::string (*write_file)(const std::string& file, const PixelsToWrite& pixels);
    /// Read the EXR in `bytes` on `threads` threads (exr_reader.h): "" on success, the size
    /// check's refusal, or nothing when the file is left to OpenImageIO.
    std::optional<std::string> (*read_memory)(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                              int threads, DecodedImage& out);
};

/// The modules' entry points, looked up by these names.
inline constexpr const char* kOiioEntryPoint = "glint_oiio_codec";
inline constexpr const char* kExrEntryPoint = "glint_exr_codec";

/// Each module's functions, loaded on the first call. Throw ImageError when the module
/// cannot be loaded.
[[nodiscard]] const Functions& oiio();
[[nodiscard]] const ExrFunctions& exr();

}  // namespace glint::codec
