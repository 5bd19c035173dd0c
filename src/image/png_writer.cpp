#include "png_writer.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

namespace glint {

namespace {

/// libpng's error callback: keep the message and return to the setjmp in write_rows (libpng
/// would print it to stderr and abort otherwise).
void on_error(png_structp png, png_const_charp message) {
    auto* error = static_cast<std::string*>(png_get_error_ptr(png));
    *error = message ? message : "libpng error";
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

/// The libpng calls, in a function of their own that holds no C++ object a longjmp would
/// skip the destructor of.
bool write_rows(std::FILE* out, int width, int height, int color_type, png_bytepp rows, std::string& error) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_error, on_warning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, out);
    // One filter (Paeth) instead of libpng's adaptive choice among five per row, and zlib
    // level 5 instead of 6: on renders the files come out within 2 % of the default's size
    // and a 640×480 image is written 20 ms sooner (docs/performance.md, "Against POV-Ray").
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_PAETH);
    png_set_compression_level(png, 5);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // The values are sRGB-encoded (image_io.cpp applies the display transform): say so.
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_text software{};
    software.compression = PNG_TEXT_COMPRESSION_NONE;
    software.key = const_cast<png_charp>("Software");
    software.text = const_cast<png_charp>("Glint");
    png_set_text(png, info, &software, 1);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string write_png(const std::filesystem::path& file, int width, int height, int channels, const uint8_t* values) {
    const int color_type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                           : channels == 2 ? PNG_COLOR_TYPE_GRAY_ALPHA
                                           : PNG_COLOR_TYPE_RGB;
    // libpng reads the rows and never writes them.
    auto* const bytes = const_cast<png_bytep>(values);
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) rows[std::size_t(y)] = bytes + std::size_t(y) * std::size_t(width) * channels;
    std::FILE* out = std::fopen(file.c_str(), "wb");
    if (!out) return "cannot write image: cannot open " + file.string();
    std::string error;
    const bool written = write_rows(out, width, height, color_type, rows.data(), error);
    const bool closed = std::fclose(out) == 0;
    if (!written) return "cannot write image: " + (error.empty() ? std::string("libpng failed") : error);
    if (!closed) return "cannot write image: write failed";
    return "";
}

}  // namespace glint
