#include "gltf_image.h"

#include "glint/math/color.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>

namespace glint {

Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name, ColorEncoding encoding) {
    if (bytes.empty()) throw ImageError(name + ": empty image data");
    // OpenImageIO picks the reader from the name's extension and falls back to sniffing
    // the bytes. In 2.4 a reader opened with a config spec takes the proxy from the spec's
    // "oiio:ioproxy" attribute (a pointer to the pointer), not from the argument. Alpha stays
    // unassociated: glTF (and PNG) colour is straight, and OIIO would premultiply it.
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    OIIO::Filesystem::IOProxy* proxy = &reader;
    OIIO::ImageSpec config;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(name, &config, &reader);
    if (!input) throw ImageError(name + ": cannot decode image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw ImageError(name + ": image has no pixels");
    Image image(spec.width, spec.height, spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw ImageError(name + ": cannot decode image: " + input->geterror());
    input->close();

    const bool integer_data = !(spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                                spec.format.basetype == OIIO::TypeDesc::HALF ||
                                spec.format.basetype == OIIO::TypeDesc::DOUBLE);
    if (encoding == ColorEncoding::Color && integer_data) {
        // Alpha is coverage, never sRGB-encoded (same rule as read_image).
        int alpha = spec.alpha_channel;
        if (alpha < 0 && (spec.nchannels == 2 || spec.nchannels == 4)) alpha = spec.nchannels - 1;
        const auto stride = std::size_t(spec.nchannels);
        for (std::size_t i = 0; i < image.pixels.size(); i += stride)
            for (int c = 0; c < std::min(spec.nchannels, 3); ++c)
                if (c != alpha) image.pixels[i + c] = srgb_to_linear(image.pixels[i + c]);
    }
    return image;
}

}  // namespace glint
