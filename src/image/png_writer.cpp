#include "png_writer.h"

#include "glint/util/byte_order.h"

#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <utility>
#include <vector>

namespace glint {

namespace {

/// Filtered bytes per stripe: each stripe is deflated on its own, in parallel (pigz's way:
/// 128 KiB pieces, each primed with the 32 KiB before it, so references reach back across
/// the seams and the file is hardly larger than one serial stream would make it). Stripes
/// are whole rows and their size depends on the image alone: any thread count writes the
/// same bytes.
constexpr std::size_t kStripeBytes = std::size_t(128) << 10;
/// Deflate's window (RFC 1951 §2): how far back a stripe's first bytes may refer.
constexpr std::size_t kWindowBytes = std::size_t(32) << 10;
/// zlib level 4 and one filter (Paeth) rather than libpng's level 6 and adaptive choice
/// among five filters per row. At 640×480 level 4 wrote two spheres in 7.1 ms and the
/// dragon in 6.4, where level 5 took 9.1 and 8.0, for files 3 to 4 % larger (93,496 and
/// 144,169 bytes); levels 1 to 3 saved up to 2 ms more but made the files 5 to 27 % larger
/// than level 5 (docs/performance.md, "Build, load and write").
constexpr int kLevel = 4;
constexpr unsigned char kPaeth = 4;

/// The Paeth predictor (PNG specification, ISO/IEC 15948 §9.4): of left, above and upper
/// left, the one closest to left + above - upper left. Branch-free, so the row loop below
/// vectorises: encoding depends on raw neighbours only.
inline int paeth(int left, int above, int upper_left) {
    const int to_left = std::abs(above - upper_left), to_above = std::abs(left - upper_left),
              to_upper_left = std::abs(left + above - 2 * upper_left);
    const int above_or_upper_left = to_above <= to_upper_left ? above : upper_left;
    return to_left <= to_above && to_left <= to_upper_left ? left : above_or_upper_left;
}

/// Row `y` as the filter byte and the Paeth differences, written to `out` (row_bytes + 1).
void filter_row(const uint8_t* values, std::size_t row_bytes, std::size_t bytes_per_pixel, int y, unsigned char* out) {
    const uint8_t* row = values + std::size_t(y) * row_bytes;
    *out++ = kPaeth;
    if (y == 0) {
        // Nothing above: the predictor is the left neighbour (or 0 in the first pixel).
        for (std::size_t i = 0; i < row_bytes; ++i)
            out[i] = static_cast<unsigned char>(row[i] - (i >= bytes_per_pixel ? row[i - bytes_per_pixel] : 0));
        return;
    }
    const uint8_t* above = row - row_bytes;
    const std::size_t lead = std::min(bytes_per_pixel, row_bytes);
    for (std::size_t i = 0; i < lead; ++i) out[i] = static_cast<unsigned char>(row[i] - above[i]);
    for (std::size_t i = lead; i < row_bytes; ++i)
        out[i] =
            static_cast<unsigned char>(row[i] - paeth(row[i - bytes_per_pixel], above[i], above[i - bytes_per_pixel]));
}

/// One stripe of rows, filtered and deflated as a raw stream (no zlib header or checksum)
/// that ends on a byte boundary, or with the final block for the last stripe.
struct Stripe {
    std::vector<unsigned char> deflated;
    uint32_t adler = 0;  ///< Adler-32 of the stripe's filtered bytes
    std::size_t filtered_size = 0;
    bool ok = false;
};

Stripe deflate_stripe(const uint8_t* values, std::size_t row_bytes, int bytes_per_pixel, int first_row, int end_row,
                      bool last) {
    // The rows before the stripe that hold the 32 KiB preceding it, filtered again here
    // (as the stripe before filters them) so the dictionary needs no other task's result.
    const std::size_t filtered_row = row_bytes + 1;
    const int context_rows =
        int(std::min<std::size_t>(std::size_t(first_row), (kWindowBytes + filtered_row - 1) / filtered_row));
    std::vector<unsigned char> filtered(std::size_t(end_row - first_row + context_rows) * filtered_row);
    for (int y = first_row - context_rows; y < end_row; ++y)
        filter_row(values, row_bytes, std::size_t(bytes_per_pixel), y,
                   filtered.data() + std::size_t(y - first_row + context_rows) * filtered_row);
    const std::size_t context = std::size_t(context_rows) * filtered_row;
    const unsigned char* input = filtered.data() + context;

    Stripe stripe;
    stripe.filtered_size = filtered.size() - context;
    stripe.adler = uint32_t(adler32_z(adler32_z(0, nullptr, 0), input, stripe.filtered_size));
    z_stream z{};
    if (deflateInit2(&z, kLevel, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return stripe;
    const std::size_t dictionary = std::min(context, kWindowBytes);
    bool ok = dictionary == 0 || deflateSetDictionary(&z, input - dictionary, uInt(dictionary)) == Z_OK;
    // A sync flush ends a middle stripe with an empty stored block: byte-aligned, not final,
    // so the next stripe's blocks follow it in one valid stream (RFC 1951 §3.2.4).
    stripe.deflated.resize(deflateBound(&z, uLong(stripe.filtered_size)) + 64);
    z.next_in = const_cast<unsigned char*>(input);
    z.avail_in = uInt(stripe.filtered_size);
    z.next_out = stripe.deflated.data();
    z.avail_out = uInt(stripe.deflated.size());
    const int result = ok ? deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH) : Z_STREAM_ERROR;
    ok = ok && (last ? result == Z_STREAM_END : result == Z_OK && z.avail_out > 0) && z.avail_in == 0;
    stripe.deflated.resize(stripe.deflated.size() - z.avail_out);
    deflateEnd(&z);
    stripe.ok = ok;
    return stripe;
}

/// Writes chunks (length, type, data, CRC-32 of type and data) to a file; remembers a failure.
class ChunkWriter {
public:
    explicit ChunkWriter(std::FILE* out) : out_(out) {}

    void raw(const void* bytes, std::size_t size) {
        ok_ = ok_ && (size == 0 || std::fwrite(bytes, 1, size, out_) == size);
    }

    /// A chunk whose data is the concatenation of `parts`.
    void chunk(const char (&type)[5], std::initializer_list<std::pair<const unsigned char*, std::size_t>> parts) {
        std::size_t length = 0;
        for (const auto& [bytes, size] : parts) length += size;
        uLong crc = crc32_z(crc32_z(0, nullptr, 0), reinterpret_cast<const unsigned char*>(type), 4);
        for (const auto& [bytes, size] : parts) crc = crc32_z(crc, bytes, size);
        raw(big_endian_bytes(uint32_t(length)).data(), 4);
        raw(type, 4);
        for (const auto& [bytes, size] : parts) raw(bytes, size);
        raw(big_endian_bytes(uint32_t(crc)).data(), 4);
    }

    bool ok() const { return ok_; }

private:
    std::FILE* out_;
    bool ok_ = true;
};

}  // namespace

std::string write_png(const std::filesystem::path& file, int width, int height, int channels, const uint8_t* values) {
    const unsigned char color_type = channels == 1 ? 0 : channels == 2 ? 4 : 2;  // grey, grey + alpha, RGB
    const std::size_t row_bytes = std::size_t(width) * std::size_t(channels);
    const int rows_per_stripe = int(std::max<std::size_t>(1, kStripeBytes / (row_bytes + 1)));
    const int stripe_count = (height + rows_per_stripe - 1) / rows_per_stripe;
    std::vector<Stripe> stripes(static_cast<std::size_t>(stripe_count));
    tbb::parallel_for(0, stripe_count, [&](int s) {
        const int first = s * rows_per_stripe, end = std::min(height, first + rows_per_stripe);
        stripes[std::size_t(s)] = deflate_stripe(values, row_bytes, channels, first, end, s + 1 == stripe_count);
    });
    uLong adler = adler32_z(0, nullptr, 0);
    for (const Stripe& stripe : stripes) {
        if (!stripe.ok) return "cannot write image: zlib failed to compress the pixels";
        adler = adler32_combine(adler, stripe.adler, z_off_t(stripe.filtered_size));
    }

    std::FILE* out = std::fopen(file.c_str(), "wb");
    if (!out) return "cannot write image: cannot open " + file.string();
    ChunkWriter png(out);
    png.raw("\x89PNG\r\n\x1a\n", 8);
    std::array<unsigned char, 13> header{};
    std::copy_n(big_endian_bytes(uint32_t(width)).begin(), 4, header.begin());
    std::copy_n(big_endian_bytes(uint32_t(height)).begin(), 4, header.begin() + 4);
    header[8] = 8;  // bits per sample; then compression, filter method and interlace: all 0
    header[9] = color_type;
    png.chunk("IHDR", {{header.data(), header.size()}});
    // The values are sRGB-encoded (image_io.cpp applies the display transform). An sRGB
    // chunk, with the gAMA and cHRM a reader without sRGB support falls back on (PNG
    // specification §11.3.3.5: gamma 1/2.2 and the sRGB primaries, in units of 10⁻⁵).
    static constexpr unsigned char gamma[] = {0x00, 0x00, 0xb1, 0x8f};
    static constexpr unsigned char perceptual[] = {0};
    static constexpr unsigned char chromaticities[] = {0,    0,    0x7a, 0x26, 0,    0,    0x80, 0x84, 0,    0,   0xfa,
                                                       0x00, 0,    0,    0x80, 0xe8, 0,    0,    0x75, 0x30, 0,   0,
                                                       0xea, 0x60, 0,    0,    0x3a, 0x98, 0,    0,    0x17, 0x70};
    static constexpr unsigned char software[] = "Software\0Glint";
    png.chunk("gAMA", {{gamma, sizeof gamma}});
    png.chunk("sRGB", {{perceptual, sizeof perceptual}});
    png.chunk("cHRM", {{chromaticities, sizeof chromaticities}});
    png.chunk("tEXt", {{software, sizeof software - 1}});
    // The zlib stream (RFC 1950): its header (deflate, 32 KiB window, "default" level
    // class, no dictionary; 0x785E is a multiple of 31), the stripes, and the Adler-32 of
    // all filtered bytes. An IDAT chunk per stripe; a reader joins their data.
    static constexpr unsigned char zlib_header[] = {0x78, 0x5e};
    const auto checksum = big_endian_bytes(uint32_t(adler));
    for (std::size_t s = 0; s < stripes.size(); ++s) {
        const bool first = s == 0, last = s + 1 == stripes.size();
        png.chunk("IDAT", {{zlib_header, first ? sizeof zlib_header : 0},
                           {stripes[s].deflated.data(), stripes[s].deflated.size()},
                           {checksum.data(), last ? checksum.size() : 0}});
    }
    png.chunk("IEND", {});
    const bool closed = std::fclose(out) == 0;
    if (!png.ok() || !closed) return "cannot write image: write failed";
    return "";
}

}  // namespace glint
