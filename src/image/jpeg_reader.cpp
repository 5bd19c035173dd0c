#include "jpeg_reader.h"

// jpeglib.h needs FILE and size_t declared before it (libjpeg.txt).
#include <cstdio>

#include <jpeglib.h>

#include <csetjmp>
#include <vector>

namespace glint::codec {

namespace {

/// libjpeg's error manager, with the place to return to on a fatal error. By default
/// libjpeg prints the message and calls exit(); here the error returns to the caller, and
/// the file is left to OpenImageIO, which words it.
struct ErrorJump {
    jpeg_error_mgr manager{};
    std::jmp_buf jump{};
};

[[noreturn]] void on_error(j_common_ptr info) { std::longjmp(reinterpret_cast<ErrorJump*>(info->err)->jump, 1); }
/// A warning (corrupt data, a file cut short, a bogus progression of scans) ends the read at
/// once, as an error does: decoding on would fill the rest with grey, or loop over scans a
/// crafted file repeats, only for the file to go to OpenImageIO after. Trace messages
/// (levels 0 and up) are dropped rather than printed.
void on_message(j_common_ptr info, int level) {
    if (level < 0) on_error(info);
}

/// The decompressor, destroyed with this. Its error manager must outlive it.
struct JpegRead {
    ErrorJump error;
    jpeg_decompress_struct info{};
    JpegRead() {
        info.err = jpeg_std_error(&error.manager);
        error.manager.error_exit = on_error;
        error.manager.emit_message = on_message;
    }
    JpegRead(const JpegRead&) = delete;
    JpegRead& operator=(const JpegRead&) = delete;
    ~JpegRead() { jpeg_destroy_decompress(&info); }
};

/// The header, with the output colour space set as OpenImageIO sets it: RGB for three
/// components, grey for one. False on a libjpeg error, or for what is left to OpenImageIO.
/// No C++ object with a destructor lives in this frame, which libjpeg's longjmp returns to.
bool read_header(JpegRead& read, const unsigned char* bytes, std::size_t size) {
    if (setjmp(read.error.jump)) return false;
    jpeg_create_decompress(&read.info);
    jpeg_mem_src(&read.info, bytes, static_cast<unsigned long>(size));
    if (jpeg_read_header(&read.info, TRUE) != JPEG_HEADER_OK) return false;
    if (read.info.num_components == 3 && read.info.jpeg_color_space != JCS_CMYK &&
        read.info.jpeg_color_space != JCS_YCCK)
        read.info.out_color_space = JCS_RGB;
    else if (read.info.num_components == 1)
        read.info.out_color_space = JCS_GRAYSCALE;
    else
        return false;
    jpeg_calc_output_dimensions(&read.info);
    return read.info.output_components == read.info.num_components;
}

/// The samples, row after row, into `samples`; false on a libjpeg error. As read_header, no
/// C++ object here.
bool read_rows(JpegRead& read, unsigned char* samples, std::size_t row_bytes) {
    if (setjmp(read.error.jump)) return false;
    jpeg_start_decompress(&read.info);
    while (read.info.output_scanline < read.info.output_height) {
        JSAMPROW row = samples + std::size_t(read.info.output_scanline) * row_bytes;
        jpeg_read_scanlines(&read.info, &row, 1);
    }
    jpeg_finish_decompress(&read.info);
    return true;
}

}  // namespace

bool is_jpeg(const unsigned char* bytes, std::size_t size) {
    return size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
}

std::optional<std::string> read_jpeg(const unsigned char* bytes, std::size_t size, const SizeCheck& check,
                                     DecodedImage& out) {
    if (!is_jpeg(bytes, size)) return std::nullopt;
    JpegRead read;
    if (!read_header(read, bytes, size)) return std::nullopt;
    const int width = int(read.info.output_width), height = int(read.info.output_height);
    const int channels = read.info.output_components;
    if (width <= 0 || height <= 0) return std::nullopt;
    if (std::string refused = check(width, height, channels); !refused.empty()) return refused;

    const std::size_t row_bytes = std::size_t(width) * std::size_t(channels);
    std::vector<unsigned char> samples(row_bytes * std::size_t(height));
    if (!read_rows(read, samples.data(), row_bytes)) return std::nullopt;

    out.width = width;
    out.height = height;
    out.channels = channels;
    out.pixels.resize(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) out.pixels[i] = float_of_byte(samples[i]);
    out.channel_names = channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
    out.alpha_channel = -1;
    out.integer_data = true;
    out.linear_tagged = false;  // OpenImageIO tags JPEG sRGB
    return std::string();
}

}  // namespace glint::codec
