#include "radiance_picture.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <new>
#include <string_view>
#include <vector>

namespace glint::codec {

namespace {

/// The bytes after the header, read front to back; every read checks what is left.
struct ByteReader {
    const unsigned char* at;
    const unsigned char* end;

    [[nodiscard]] std::size_t left() const { return std::size_t(end - at); }
};

/// One line of the header without its '\n'; nothing when no '\n' is left.
std::optional<std::string_view> next_line(ByteReader& in) {
    for (const unsigned char* p = in.at; p < in.end; ++p)
        if (*p == '\n') {
            const std::string_view line(reinterpret_cast<const char*>(in.at), std::size_t(p - in.at));
            in.at = p + 1;
            return line;
        }
    return std::nullopt;
}

/// A positive decimal at the front of `text`, which it then drops.
std::optional<int> take_size(std::string_view& text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || value <= 0) return std::nullopt;
    text.remove_prefix(std::size_t(end - text.data()));
    return value;
}

bool take(std::string_view& text, std::string_view prefix) {
    if (!text.starts_with(prefix)) return false;
    text.remove_prefix(prefix.size());
    return true;
}

/// Radiance's conversion as rgbe.c does it: the three mantissas share the exponent, biased
/// by 128, and are read as byte / 256 (not Ward's (byte + 0.5) / 256, so that 1.0 stays 1.0).
/// Exact in float: eight significant bits, at worst 2^-135, above the smallest subnormal.
/// The 256 scales are powers of two, so byte × scale is the same exact value as ldexp's.
void rgbe_to_float(const unsigned char rgbe[4], float* rgb) {
    static const std::array<float, 256> kScale = [] {
        std::array<float, 256> scale{};
        for (int e = 1; e < 256; ++e) scale[std::size_t(e)] = std::ldexp(1.0f, e - (128 + 8));
        return scale;
    }();
    const float scale = kScale[rgbe[3]];
    for (int c = 0; c < 3; ++c) rgb[c] = float(rgbe[c]) * scale;
}

/// Scanline y stored flat, four bytes a pixel.
std::string read_flat_scanline(ByteReader& in, int width, int y, float* out) {
    if (in.left() / 4 < std::size_t(width))
        return "the pixels end early: scanline " + std::to_string(y + 1) + " is cut off";
    for (int x = 0; x < width; ++x, in.at += 4, out += 3) rgbe_to_float(in.at, out);
    return "";
}

/// One run-length coded scanline (after its four-byte mark): each channel in turn, as runs
/// (a count above 128, then the byte repeated count − 128 times) and literals (a count up
/// to 128, then that many bytes). `planes` receives the four channels one after another.
std::string read_coded_scanline(ByteReader& in, int width, int y, unsigned char* planes) {
    const auto w = std::size_t(width);
    for (int channel = 0; channel < 4; ++channel) {
        unsigned char* out = planes + std::size_t(channel) * w;
        const unsigned char* const plane_end = out + w;
        while (out < plane_end) {
            if (in.left() < 2) return "the pixels end early: scanline " + std::to_string(y + 1) + " is cut off";
            const unsigned count_byte = *in.at++;
            const bool run = count_byte > 128;
            const std::size_t count = run ? count_byte - 128 : count_byte;
            if (count == 0 || count > std::size_t(plane_end - out))
                return "scanline " + std::to_string(y + 1) + " has a run of " + std::to_string(count) +
                       " bytes where " + std::to_string(plane_end - out) + " are left to fill";
            if (run) {
                std::fill(out, out + count, *in.at++);
            } else {
                if (in.left() < count) return "the pixels end early: scanline " + std::to_string(y + 1) + " is cut off";
                std::copy(in.at, in.at + count, out);
                in.at += count;
            }
            out += count;
        }
    }
    return "";
}

/// Whether scanlines `width` pixels wide may be run-length coded: the coding is defined for
/// 8 to 32767 pixels.
bool may_be_coded(int width) { return width >= 8 && width <= 0x7fff; }

std::string read_pixels(ByteReader& in, int width, int height, float* pixels) {
    // Each scanline says whether it is coded: a coded one starts with 2, 2 and its width
    // below 32768, which no flat pixel does (a stored pixel's largest mantissa is at least
    // 128), as Radiance's own reader tells them apart.
    const bool codable = may_be_coded(width);
    const auto w = std::size_t(width);
    std::vector<unsigned char> planes(codable ? 4 * w : 0);
    for (int y = 0; y < height; ++y) {
        float* out = pixels + std::size_t(y) * w * 3;
        if (!codable || in.left() < 4 || in.at[0] != 2 || in.at[1] != 2 || (in.at[2] & 0x80) != 0) {
            if (std::string error = read_flat_scanline(in, width, y, out); !error.empty()) return error;
            continue;
        }
        const int stored_width = int(in.at[2]) << 8 | int(in.at[3]);
        if (stored_width != width)
            return "scanline " + std::to_string(y + 1) + " says it is " + std::to_string(stored_width) +
                   " pixels wide; expected " + std::to_string(width) + " as the header says";
        in.at += 4;
        if (std::string error = read_coded_scanline(in, width, y, planes.data()); !error.empty()) return error;
        for (std::size_t x = 0; x < w; ++x, out += 3) {
            const unsigned char rgbe[4] = {planes[x], planes[w + x], planes[2 * w + x], planes[3 * w + x]};
            rgbe_to_float(rgbe, out);
        }
    }
    return "";
}

}  // namespace

bool is_radiance_picture(const unsigned char* bytes, std::size_t size) {
    return size >= 2 && bytes[0] == '#' && bytes[1] == '?';
}

std::optional<std::string> read_radiance_picture(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                                 Image& out) {
    ByteReader in{bytes, bytes + size};
    if (!is_radiance_picture(bytes, size) || !next_line(in))
        return "not a Radiance picture (expected a first line starting with #?)";
    // Header lines up to an empty one; only FORMAT matters (EXPOSURE, GAMMA, VIEW... are notes).
    for (;;) {
        const std::optional<std::string_view> line = next_line(in);
        if (!line) return std::string("the header ends without the empty line that closes it");
        if (line->empty()) break;
        if (std::string_view format = *line; take(format, "FORMAT=") && format != "32-bit_rle_rgbe")
            return "the pixels are stored as " + std::string(format) + "; expected FORMAT=32-bit_rle_rgbe";
    }
    const std::optional<std::string_view> resolution = next_line(in);
    if (!resolution) return std::string("the header ends without the resolution line (expected -Y height +X width)");
    std::string_view text = *resolution;
    const bool standard = take(text, "-Y ");
    if (!standard) {
        if (text.size() > 1 && (text[0] == '-' || text[0] == '+') && (text[1] == 'X' || text[1] == 'Y'))
            return std::nullopt;
        return "the resolution line is '" + std::string(*resolution) + "'; expected -Y height +X width";
    }
    const std::optional<int> height = take_size(text);
    const bool has_x = height && take(text, " +X ");
    const std::optional<int> width = has_x ? take_size(text) : std::nullopt;
    if (!width || !text.empty())
        return "the resolution line is '" + std::string(*resolution) + "'; expected -Y height +X width";
    if (std::string refused = check(*width, *height, 3); !refused.empty()) return refused;
    // A flat scanline takes 4 bytes a pixel; a coded one at least 4 bytes of mark and 2 for
    // each 127 bytes of a channel: a picture whose bytes cannot hold the smaller of the two
    // is refused before its pixels are allocated.
    const auto flat = 4 * std::size_t(*width);
    const auto per_scanline = may_be_coded(*width) ? std::min(flat, 4 + 8 * ((std::size_t(*width) + 126) / 127)) : flat;
    if (in.left() / per_scanline < std::size_t(*height))
        return "the pixels end early: " + std::to_string(in.left()) + " bytes cannot hold " + std::to_string(*width) +
               "×" + std::to_string(*height) + " pixels";
    Image image;
    try {
        image = Image(*width, *height, 3);
    } catch (const std::bad_alloc&) {
        return "cannot read image: out of memory for " + std::to_string(*width) + "×" + std::to_string(*height) +
               " pixels";
    }
    if (std::string error = read_pixels(in, *width, *height, image.pixels.data()); !error.empty()) return error;
    image.channel_names = {"R", "G", "B"};
    out = std::move(image);
    return "";
}

}  // namespace glint::codec
