/// \file Fuzz target: an image file as scenes use them, as a texture (read_image, colour and
/// data encodings), as an environment map (load_environment) and as bytes embedded in a GLB
/// (decode_image). The first byte of the input picks the file's extension, the rest is
/// the file: OpenImageIO tries the extension's reader first, then sniffs the bytes.

#include "fuzz_harness.h"

#include "glint/image/image_io.h"
#include "glint/scene/environment.h"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    constexpr std::array<const char*, 10> kExtensions = {".png", ".jpg", ".exr", ".hdr", ".pfm",
                                                         ".tga", ".bmp", ".tif", ".ppm", ".gif"};
    const std::string name = std::string("image") + kExtensions[data[0] % kExtensions.size()];
    const std::string_view bytes = glint::fuzz::as_text(data + 1, size - 1);
    const glint::fuzz::ScratchFolder folder;
    const std::filesystem::path file = folder.write(name, bytes);
    try {
        (void)glint::read_image(file, glint::ColorEncoding::Data);
        (void)glint::average_radiance(glint::load_environment(file));
    } catch (const glint::ImageError&) {
    } catch (const std::invalid_argument&) {  // load_environment: a layout it cannot guess
    }
    try {
        (void)glint::decode_image(std::vector<unsigned char>(bytes.begin(), bytes.end()), name);
    } catch (const glint::ImageError&) {
    }
    return 0;
}
