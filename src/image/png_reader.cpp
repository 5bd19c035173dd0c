#include "png_reader.h"

#include <png.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace glint::codec {

static_assert(std::endian::native == std::endian::little, "16-bit samples are swapped to little-endian");

namespace {

/// The bytes libpng reads, in memory.
struct Source {
    const unsigned char* bytes = nullptr;
    std::size_t size = 0, at = 0;
};

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
    auto* source = static_cast<Source*>(png_get_io_ptr(png));
    if (n > source->size - source->at) png_error(png, "the file ends early");
    std::memcpy(out, source->bytes + source->at, n);
    source->at += n;
}

// libpng reports errors by calling these; by default it prints them to stderr first. Any
// error here leaves the file to OpenImageIO, which words it.
[[noreturn]] void on_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_warning(png_structp, png_const_charp) {}

/// libpng's read and info structs, destroyed with this.
struct PngRead {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    PngRead() = default;
    PngRead(const PngRead&) = delete;
    PngRead& operator=(const PngRead&) = delete;
    ~PngRead() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

/// What the header says once libpng expands the samples as OpenImageIO asks it to.
struct Header {
    png_uint_32 width = 0, height = 0;
    int bit_depth = 0, channels = 0;
    std::size_t row_bytes = 0;
    bool linear = false;
    /// What this reader leaves to OpenImageIO: an image offset, or Glint's own text.
    bool unusual = false;
};

/// The header, with the transformations set (palette to RGB, tRNS to alpha, 1-, 2- and
/// 4-bit samples to 8: png_set_expand, as OpenImageIO's png_pvt.h). False on a libpng error.
/// No C++ object with a destructor lives in this frame, which libpng's longjmp returns to.
bool read_header(png_structp png, png_infop info, Header& header) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_set_expand(png);
    png_set_swap(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    header.width = png_get_image_width(png, info);
    header.height = png_get_image_height(png, info);
    header.bit_depth = png_get_bit_depth(png, info);
    header.channels = png_get_channels(png, info);
    header.row_bytes = png_get_rowbytes(png, info);
    // OpenImageIO tags the values linear when there is no sRGB chunk and the gAMA chunk's
    // gamma, rounded to hundredths, is 1.
    int intent = 0;
    double gamma = 0.0;
    if (!png_get_sRGB(png, info, &intent) && png_get_gAMA(png, info, &gamma) && gamma > 0.0) {
        const float display_gamma = std::round(100.0f * float(1.0 / gamma)) / 100.0f;
        header.linear = display_gamma == 1.0f;
    }
    png_int_32 x = 0, y = 0;
    int unit = 0;
    header.unusual = png_get_oFFs(png, info, &x, &y, &unit) != 0;
    png_textp text = nullptr;
    const int texts = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < texts; ++i)
        if (std::strncmp(text[i].key, kAttributePrefix.c_str(), kAttributePrefix.size()) == 0) header.unusual = true;
    return true;
}

/// The samples into `rows`; false on a libpng error. As read_header, no C++ object here.
bool read_rows(png_structp png, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

}  // namespace

bool is_png(const unsigned char* bytes, std::size_t size) { return size >= 8 && png_sig_cmp(bytes, 0, 8) == 0; }

std::optional<std::string> read_png(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                    DecodedImage& out) {
    PngRead read;
    if (!read.info) return std::nullopt;
    Source source{bytes, size, 0};
    png_set_read_fn(read.png, &source, read_bytes);
    Header header;
    if (!read_header(read.png, read.info, header) || header.unusual) return std::nullopt;
    if (header.width == 0 || header.height == 0 || header.channels < 1 || header.channels > 4) return std::nullopt;
    const int width = int(header.width), height = int(header.height), channels = header.channels;
    if (std::string refused = check(width, height, channels); !refused.empty()) return refused;

    std::vector<unsigned char> samples(header.row_bytes * header.height);
    std::vector<png_bytep> rows(header.height);
    for (png_uint_32 y = 0; y < header.height; ++y) rows[y] = samples.data() + y * header.row_bytes;
    if (!read_rows(read.png, rows.data())) return std::nullopt;

    const std::size_t values = std::size_t(width) * std::size_t(height) * std::size_t(channels);
    out.width = width;
    out.height = height;
    out.channels = channels;
    out.pixels.resize(values);
    // OpenImageIO's integer-to-float conversion: the value times the reciprocal of the
    // largest one, in float.
    if (header.bit_depth == 16) {
        for (std::size_t i = 0; i < values; ++i) {
            uint16_t v = 0;
            std::memcpy(&v, samples.data() + 2 * i, 2);
            out.pixels[i] = float(v) * (1.0f / 65535.0f);
        }
    } else {
        for (std::size_t i = 0; i < values; ++i) out.pixels[i] = float_of_byte(samples[i]);
    }
    static const std::vector<std::string> kNames[4] = {{"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    out.channel_names = kNames[channels - 1];
    out.alpha_channel = channels == 2 ? 1 : channels == 4 ? 3 : -1;
    out.integer_data = true;
    out.linear_tagged = header.linear;
    return std::string();
}

}  // namespace glint::codec
