#include "glint/image/image_io.h"

#include "bmp_header.h"
#include "exr_reader.h"
#include "image_codec.h"
#include "jpeg_reader.h"
#include "png_chunks.h"
#include "png_reader.h"
#include "png_writer.h"
#include "radiance_picture.h"

#include "glint/image/srgb_byte.h"
#include "glint/math/color.h"
#include "glint/util/file_extension.h"
#include "glint/util/move_into_place.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

namespace glint {

namespace {

bool is_float_format(const std::string& ext) { return ext == ".exr" || ext == ".hdr" || ext == ".pfm"; }

/// Portable float map (PFM): "PF" header, width height, -1.0 (little-endian), then RGB float
/// rows from the bottom up. OpenImageIO 2.4 (Debian 12) reads PFM but has no writer for it.
bool write_pfm(const std::filesystem::path& path, const Image& image, const std::vector<float>& rgb) {
    std::FILE* f = std::fopen(path.string().c_str(), "wb");
    if (!f) return false;
    bool ok = std::fprintf(f, "PF\n%d %d\n-1.0\n", image.width, image.height) > 0;
    const auto row = std::size_t(image.width) * 3;
    for (int y = image.height - 1; ok && y >= 0; --y)
        ok = std::fwrite(&rgb[std::size_t(y) * row], sizeof(float), row, f) == row;
    return std::fclose(f) == 0 && ok;
}

constexpr std::array<const char*, 8> kOutputExtensions = {".exr", ".hdr",  ".pfm", ".png",
                                                          ".jpg", ".jpeg", ".tif", ".tiff"};

/// The size check every read makes before allocating: a header may claim any size; refuse
/// one beyond a fixed budget (a 58-byte .hdr claiming 100000×100000 gave only
/// "std::bad_alloc"; OpenImageIO 2.4 asked for 12.8 GB of scratch to read one row of a BMP
/// claiming 16711664×8, found by fuzz/fuzz_image). Fixed rather than the machine's memory,
/// so that a file loads or fails the same everywhere.
std::string check_size(int width, int height, int channels) {
    const double values = double(width) * double(height) * double(channels);
    if (width <= kMaxImageSide && height <= kMaxImageSide && values <= double(kMaxImageValues)) return "";
    return "a " + std::to_string(width) + "×" + std::to_string(height) + " image with " + std::to_string(channels) +
           " channels is too large (expected at most " + std::to_string(kMaxImageSide) + " pixels a side and " +
           std::to_string(kMaxImageValues) + " values, a 16384×8192 RGBA image)";
}

/// srgb_to_linear(v), by table where `v` is one of the 256 values of an 8-bit level (as the
/// readers make them: codec::float_of_byte), so the result is the function's own, bit for
/// bit. powf on every texel was a third of the CPU time of loading a glTF asset's JPEG
/// textures (docs/performance.md, "JPEG textures without OpenImageIO").
float srgb_to_linear_of_level(float v) {
    static const std::array<float, 256> kLinear = [] {
        std::array<float, 256> table{};
        for (int level = 0; level < 256; ++level) table[level] = srgb_to_linear(codec::float_of_byte(unsigned(level)));
        return table;
    }();
    const float scaled = v * 255.0f;
    if (scaled >= 0.0f && scaled <= 255.0f) {
        const auto level = static_cast<int>(scaled + 0.5f);
        if (codec::float_of_byte(unsigned(level)) == v) return kLinear[std::size_t(level)];
    }
    return srgb_to_linear(v);
}

/// The decoded image as linear floats. Integer files hold display-encoded colour unless they
/// say otherwise; float files are linear. Alpha is coverage, never sRGB-encoded.
Image linear_image(codec::DecodedImage decoded, ColorEncoding encoding) {
    Image image;
    image.width = decoded.width;
    image.height = decoded.height;
    image.channels = decoded.channels;
    image.pixels = std::move(decoded.pixels);
    image.channel_names = std::move(decoded.channel_names);
    image.region = {decoded.x, decoded.y, decoded.frame_width, decoded.frame_height};
    image.attributes = std::move(decoded.attributes);
    if (encoding == ColorEncoding::Color && decoded.integer_data && !decoded.linear_tagged) {
        // Grey+alpha and RGBA files without an alpha tag keep their last channel as alpha.
        int alpha = decoded.alpha_channel;
        if (alpha < 0 && (image.channels == 2 || image.channels == 4)) alpha = image.channels - 1;
        const auto stride = std::size_t(image.channels);
        const int colours = std::min(image.channels, 3);
        // Each value on its own, so the pixels are shared out among threads.
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, image.pixels.size() / stride, 1 << 14),
                          [&](const tbb::blocked_range<std::size_t>& pixels) {
                              for (std::size_t p = pixels.begin(); p < pixels.end(); ++p)
                                  for (int c = 0; c < colours; ++c)
                                      if (c != alpha) {
                                          float& v = image.pixels[p * stride + std::size_t(c)];
                                          v = srgb_to_linear_of_level(v);
                                      }
                          });
    }
    return image;
}

/// The Radiance picture in `bytes` as Glint reads it (radiance_picture.h): linear floats,
/// whichever encoding integer files would be read with. Nothing when the bytes are another
/// format or a picture left to OpenImageIO; an ImageError naming `name` when it is broken.
std::optional<Image> native_radiance_picture(const unsigned char* bytes, std::size_t size, const std::string& name) {
    if (!codec::is_radiance_picture(bytes, size)) return std::nullopt;
    Image image;
    const std::optional<std::string> error = codec::read_radiance_picture(bytes, size, check_size, image);
    if (!error) return std::nullopt;
    if (!error->empty()) throw ImageError(name + ": " + *error);
    return image;
}

/// Glint's own decoder of a PNG, JPEG or EXR (png_reader.h, jpeg_reader.h through libpng and
/// libjpeg; exr_reader.h through OpenEXR, decompressed on the threads the caller may use).
using NativeDecoder = std::optional<std::string> (*)(const unsigned char* bytes, std::size_t size,
                                                     codec::DecodedImage& out);

/// The decoder for the format `bytes` begin with, or none: the one list of the formats that
/// read_image() reads whole and native_decoded_image() decodes.
NativeDecoder native_decoder(const unsigned char* bytes, std::size_t size) {
    if (codec::is_png(bytes, size))
        return [](const unsigned char* b, std::size_t n, codec::DecodedImage& out) {
            return codec::read_png(b, n, check_size, out);
        };
    if (codec::is_jpeg(bytes, size))
        return [](const unsigned char* b, std::size_t n, codec::DecodedImage& out) {
            return codec::read_jpeg(b, n, check_size, out);
        };
    if (codec::is_exr(bytes, size))
        return [](const unsigned char* b, std::size_t n, codec::DecodedImage& out) {
            return codec::exr().read_memory(b, n, check_size, tbb::this_task_arena::max_concurrency(), out);
        };
    return nullptr;
}

/// The PNG, JPEG or EXR in `bytes` as Glint reads it. Nothing when the bytes are another
/// format or a file left to OpenImageIO; an ImageError naming `name` when it is too large.
std::optional<Image> native_decoded_image(const unsigned char* bytes, std::size_t size, const std::string& name,
                                          ColorEncoding encoding) {
    const NativeDecoder decode = native_decoder(bytes, size);
    if (!decode) return std::nullopt;
    codec::DecodedImage decoded;
    const std::optional<std::string> error = decode(bytes, size, decoded);
    if (!error) return std::nullopt;
    if (!error->empty()) throw ImageError(name + ": " + *error);
    return linear_image(std::move(decoded), encoding);
}

}  // namespace

Image read_image(const std::filesystem::path& path, ColorEncoding encoding) {
    if (!std::filesystem::exists(path)) throw ImageError(path.string() + ": no such image file");
    std::ifstream file(path, std::ios::binary);
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);  // 0 for a folder: not a PNG
    const ByteRangeReader read_file = [&](uint64_t offset, unsigned char* out, std::size_t n) {
        file.clear();
        return bool(file.seekg(std::streamoff(offset)).read(reinterpret_cast<char*>(out), std::streamsize(n)));
    };
    check_png_chunks(size, read_file, path.string());
    check_bmp_header(size, read_file, path.string());
    // A Radiance picture, a PNG, a JPEG or an EXR is read whole, from the stream already
    // open, by Glint itself (the EXR by OpenEXR alone).
    unsigned char magic[8] = {};
    file.clear();
    file.seekg(0).read(reinterpret_cast<char*>(magic), sizeof magic);
    const auto magic_size = std::size_t(file.gcount());
    const bool radiance = codec::is_radiance_picture(magic, std::min<std::size_t>(magic_size, 2));
    if (radiance || native_decoder(magic, magic_size)) {
        std::string bytes(size, '\0');
        file.clear();
        if (!file.seekg(0).read(bytes.data(), std::streamsize(size)))
            throw ImageError(path.string() + ": cannot read image: the file cannot be read whole");
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        std::optional<Image> image = radiance ? native_radiance_picture(data, size, path.string())
                                              : native_decoded_image(data, size, path.string(), encoding);
        if (image) return std::move(*image);
    }
    codec::DecodedImage decoded;
    if (const std::string error = codec::oiio().read_file(path.string(), check_size, decoded); !error.empty())
        throw ImageError(path.string() + ": " + error);
    return linear_image(std::move(decoded), encoding);
}

Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name, ColorEncoding encoding) {
    if (bytes.empty()) throw ImageError(name + ": empty image data");
    const ByteRangeReader read_bytes = [&](uint64_t offset, unsigned char* out, std::size_t n) {
        if (offset > bytes.size() || n > bytes.size() - offset) return false;
        std::memcpy(out, bytes.data() + offset, n);
        return true;
    };
    check_png_chunks(bytes.size(), read_bytes, name);
    check_bmp_header(bytes.size(), read_bytes, name);
    if (std::optional<Image> image = native_radiance_picture(bytes.data(), bytes.size(), name))
        return std::move(*image);
    if (std::optional<Image> image = native_decoded_image(bytes.data(), bytes.size(), name, encoding))
        return std::move(*image);
    codec::DecodedImage decoded;
    if (const std::string error = codec::oiio().read_memory(bytes.data(), bytes.size(), name, check_size, decoded);
        !error.empty())
        throw ImageError(name + ": " + error);
    return linear_image(std::move(decoded), encoding);
}

bool keeps_radiance(const std::filesystem::path& path) { return is_float_format(lower_case_extension(path)); }

bool is_supported_output(const std::filesystem::path& path) {
    const std::string ext = lower_case_extension(path);
    return std::find(kOutputExtensions.begin(), kOutputExtensions.end(), ext) != kOutputExtensions.end();
}

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
    // A unique temporary name beside the target keeps the rename atomic and on one file system.
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string name = ".";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "." + string
    name += path.stem().string();
    name += ".partial-";
    name += std::to_string(::getpid());
    name += lower_case_extension(path);
    return dir / name;
}

void check_output_path(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw ImageError(path.string() + ": is a folder; expected the name of an image file to write");
    if (!is_supported_output(path))
        throw ImageError(path.string() + ": unknown image extension '" + lower_case_extension(path) +
                         "' (expected .exr, .hdr, .pfm, .png, .jpg or .tif)");
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(dir, ec))
        throw ImageError(path.string() + ": the folder " + dir.string() + " does not exist");
    // The image is written beside its final name and renamed: the folder must be writable.
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        throw ImageError(path.string() + ": cannot write into the folder " + dir.string() + " (" +
                         std::error_code(errno, std::generic_category()).message() + ")");
}

void write_image(const std::filesystem::path& path, const Image& image, const WriteOptions& options) {
    check_output_path(path);
    const std::string ext = lower_case_extension(path);
    if (image.empty()) throw ImageError(path.string() + ": nothing to write (empty image)");

    const bool keep_linear = is_float_format(ext);
    // EXR keeps every named channel; the other formats take R, G, B.
    const bool named = ext == ".exr" && image.channel_names.size() == std::size_t(image.channels);
    const int channels = named ? image.channels : std::min(image.channels, 3);
    const std::size_t pixel_count = std::size_t(image.width) * image.height;
    // PNG takes the 8-bit values straight from the conversion; the other formats take floats
    // (OpenImageIO quantises for JPEG and TIFF). Neither buffer is zeroed first: the
    // parallel loop writes every value, and its threads share the first touch of each page.
    const bool png = ext == ".png";
    const auto data = png ? nullptr : std::make_unique_for_overwrite<float[]>(pixel_count * channels);
    const auto bytes = png ? std::make_unique_for_overwrite<uint8_t[]>(pixel_count * channels) : nullptr;
    const float gain = std::exp2(options.exposure);
    // Pixel by pixel, in parallel: the sRGB curve's powf for every value of a full-HD frame
    // is tens of milliseconds on one thread.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixel_count, 1u << 14), [&](const auto& range) {
        for (std::size_t p = range.begin(); p < range.end(); ++p) {
            const float* in = &image.pixels[p * image.channels];
            const std::size_t first = p * channels;
            if (keep_linear) {
                std::copy(in, in + channels, &data[first]);
                continue;
            }
            float toned[3];
            if (channels == 3) {
                const Color c = apply_tone_curve(options.tone_curve, Color(in[0], in[1], in[2]) * gain);
                toned[0] = c.r;
                toned[1] = c.g;
                toned[2] = c.b;
            } else {
                for (int c = 0; c < channels; ++c)
                    toned[c] = apply_tone_curve(options.tone_curve, Color(in[c] * gain)).r;
            }
            for (int c = 0; c < channels; ++c) {
                if (png)
                    bytes[first + c] = srgb_byte(toned[c]);
                else
                    data[first + c] = linear_to_srgb(toned[c]);
            }
        }
    });

    const std::filesystem::path tmp = temporary_path_for(path);
    std::string error;
    if (ext == ".pfm") {
        std::vector<float> rgb(pixel_count * 3);
        for (std::size_t p = 0; p < pixel_count; ++p)
            for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = data[p * channels + std::min(c, channels - 1)];
        if (!write_pfm(tmp, image, rgb)) error = "cannot write image: write failed";
    } else if (png) {
        error = write_png(tmp, image.width, image.height, channels, bytes.get());
    } else {
        // Only EXR keeps where the pixels lie in a frame, and text beside them.
        const bool exr = ext == ".exr";
        const FrameRegion region = exr ? image.region : FrameRegion{};
        const codec::PixelsToWrite pixels{image.width,
                                          image.height,
                                          channels,
                                          data.get(),
                                          keep_linear,
                                          named ? &image.channel_names : nullptr,
                                          region.x,
                                          region.y,
                                          region.frame_width,
                                          region.frame_height,
                                          exr ? &image.attributes : nullptr,
                                          tbb::this_task_arena::max_concurrency()};
        error = exr ? codec::exr().write_file(tmp.string(), pixels)
                    : codec::oiio().write_file(path.string(), tmp.string(), pixels);
    }
    if (!error.empty()) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw ImageError(path.string() + ": " + error);
    }
    if (const std::string reason = move_into_place(tmp, path); !reason.empty())
        throw ImageError(path.string() + ": cannot move the finished image into place: " + reason);
}

}  // namespace glint
