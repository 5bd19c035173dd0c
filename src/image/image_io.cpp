#include "glint/image/image_io.h"

#include "png_chunks.h"

#include "glint/math/color.h"
#include "glint/util/file_extension.h"
#include "glint/util/move_into_place.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

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

}  // namespace

namespace {

/// Pixels of an opened image as linear floats. Integer files hold display-encoded colour
/// unless they say otherwise; float files are linear. Alpha is coverage, never sRGB-encoded.
Image read_pixels(OIIO::ImageInput& input, const std::string& name, ColorEncoding encoding) {
    const OIIO::ImageSpec& spec = input.spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw ImageError(name + ": image has no pixels");
    // A header may claim any size; refuse one beyond a fixed budget before allocating (a
    // 58-byte .hdr claiming 100000×100000 gave only "std::bad_alloc"; OpenImageIO 2.4 asked
    // for 12.8 GB of scratch to read one row of a BMP claiming 16711664×8, found by
    // fuzz/fuzz_image). Fixed rather than the machine's memory, so that a file loads or
    // fails the same everywhere.
    const double values = double(spec.width) * double(spec.height) * double(spec.nchannels);
    if (spec.width > kMaxImageSide || spec.height > kMaxImageSide || values > double(kMaxImageValues))
        throw ImageError(name + ": a " + std::to_string(spec.width) + "×" + std::to_string(spec.height) +
                         " image with " + std::to_string(spec.nchannels) + " channels is too large (expected at most " +
                         std::to_string(kMaxImageSide) + " pixels a side and " + std::to_string(kMaxImageValues) +
                         " values, a 16384×8192 RGBA image)");
    Image image(spec.width, spec.height, spec.nchannels);
    if (!input.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw ImageError(name + ": cannot read image: " + input.geterror());
    input.close();
    image.channel_names.assign(spec.channelnames.begin(), spec.channelnames.end());

    const bool integer_data =
        !(spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
          spec.format.basetype == OIIO::TypeDesc::DOUBLE);
    const std::string color_space = spec.get_string_attribute("oiio:ColorSpace");
    const bool linear_tagged = color_space == "Linear" || color_space == "linear";
    if (encoding == ColorEncoding::Color && integer_data && !linear_tagged) {
        // Grey+alpha and RGBA files without an alpha tag keep their last channel as alpha.
        int alpha = spec.alpha_channel;
        if (alpha < 0 && (spec.nchannels == 2 || spec.nchannels == 4)) alpha = spec.nchannels - 1;
        const auto stride = std::size_t(spec.nchannels);
        for (std::size_t i = 0; i < image.pixels.size(); i += stride)
            for (int c = 0; c < std::min(spec.nchannels, 3); ++c)
                if (c != alpha) image.pixels[i + c] = srgb_to_linear(image.pixels[i + c]);
    }
    return image;
}

/// Bytes in memory as OpenImageIO reads them, refusing offsets outside the bytes. OpenImageIO
/// 2.4's IOMemReader takes any offset a reader asks for: a corrupt EXR's chunk table made
/// OpenEXR read one byte before the buffer (a heap overflow found by fuzz/fuzz_image,
/// regressions/fuzz_image/exr_chunk_offset_before_buffer). A derived class, not a sibling,
/// so that readers that treat a "memreader" proxy as an IOMemReader still may.
class BoundedMemoryReader final : public OIIO::Filesystem::IOMemReader {
public:
    using IOMemReader::IOMemReader;

    bool seek(int64_t offset) override {
        if (offset < 0 || offset > int64_t(m_buf.size())) return false;
        m_pos = offset;
        return true;
    }
    size_t read(void* out, size_t size) override {
        const size_t n = pread(out, size, m_pos);
        m_pos += int64_t(n);
        return n;
    }
    size_t pread(void* out, size_t size, int64_t offset) override {
        if (offset < 0 || offset >= int64_t(m_buf.size())) return 0;
        const size_t n = std::min(size, size_t(int64_t(m_buf.size()) - offset));
        std::memcpy(out, m_buf.data() + offset, n);
        return n;
    }
};

/// Straight (unassociated) alpha: colour textures with cut-outs must keep their colour at
/// the edges, which OpenImageIO's default premultiplication would darken.
OIIO::ImageSpec straight_alpha_config() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

}  // namespace

Image read_image(const std::filesystem::path& path, ColorEncoding encoding) {
    if (!std::filesystem::exists(path)) throw ImageError(path.string() + ": no such image file");
    std::ifstream file(path, std::ios::binary);
    std::error_code ec;
    const uint64_t size = std::filesystem::file_size(path, ec);  // 0 for a folder: not a PNG
    check_png_chunks(
        size,
        [&](uint64_t offset, unsigned char* out, std::size_t n) {
            return bool(file.seekg(std::streamoff(offset)).read(reinterpret_cast<char*>(out), std::streamsize(n)));
        },
        path.string());
    const OIIO::ImageSpec config = straight_alpha_config();
    auto input = OIIO::ImageInput::open(path.string(), &config);
    if (!input) throw ImageError(path.string() + ": cannot read image: " + OIIO::geterror());
    return read_pixels(*input, path.string(), encoding);
}

Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name, ColorEncoding encoding) {
    if (bytes.empty()) throw ImageError(name + ": empty image data");
    check_png_chunks(
        bytes.size(),
        [&](uint64_t offset, unsigned char* out, std::size_t n) {
            if (offset > bytes.size() || n > bytes.size() - offset) return false;
            std::memcpy(out, bytes.data() + offset, n);
            return true;
        },
        name);
    // OpenImageIO picks the reader from the name's extension and falls back to sniffing the
    // bytes. In 2.4 a reader opened with a config spec takes the proxy from the spec's
    // "oiio:ioproxy" attribute (a pointer to the pointer), not only from the argument.
    BoundedMemoryReader reader(bytes.data(), bytes.size());
    OIIO::Filesystem::IOProxy* proxy = &reader;
    OIIO::ImageSpec config = straight_alpha_config();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto input = OIIO::ImageInput::open(name, &config, &reader);
    if (!input) throw ImageError(name + ": cannot decode image: " + OIIO::geterror());
    return read_pixels(*input, name, encoding);
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
    std::vector<float> data(std::size_t(image.width) * image.height * channels);
    const float gain = std::exp2(options.exposure);
    for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p) {
        const float* in = &image.pixels[p * image.channels];
        float* out = &data[p * channels];
        if (keep_linear) {
            std::copy(in, in + channels, out);
        } else if (channels == 3) {
            const Color display = apply_tone_curve(options.tone_curve, Color(in[0], in[1], in[2]) * gain);
            for (int c = 0; c < 3; ++c) out[c] = linear_to_srgb(display[c]);
        } else {
            for (int c = 0; c < channels; ++c)
                out[c] = linear_to_srgb(apply_tone_curve(options.tone_curve, Color(in[c] * gain)).r);
        }
    }

    const std::filesystem::path tmp = temporary_path_for(path);
    std::string error;
    if (ext == ".pfm") {
        std::vector<float> rgb(std::size_t(image.width) * image.height * 3);
        for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
            for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = data[p * channels + std::min(c, channels - 1)];
        if (!write_pfm(tmp, image, rgb)) error = "write failed";
    } else {
        auto output = OIIO::ImageOutput::create(path.string());
        if (!output) throw ImageError(path.string() + ": cannot create a writer: " + OIIO::geterror());
        OIIO::ImageSpec spec(image.width, image.height, channels,
                             keep_linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
        if (named) {
            spec.channelnames = image.channel_names;
            spec.alpha_channel = -1;  // no channel is coverage: a fourth one is a count or an AOV
        }
        spec.attribute("oiio:ColorSpace", keep_linear ? "Linear" : "sRGB");
        spec.attribute("Software", "Glint");
        if (!(output->open(tmp.string(), spec) && output->write_image(OIIO::TypeDesc::FLOAT, data.data()) &&
              output->close()))
            error = output->geterror();
    }
    if (!error.empty()) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw ImageError(path.string() + ": cannot write image: " + error);
    }
    if (const std::string reason = move_into_place(tmp, path); !reason.empty())
        throw ImageError(path.string() + ": cannot move the finished image into place: " + reason);
}

}  // namespace glint
