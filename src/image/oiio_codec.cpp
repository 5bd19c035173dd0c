/// libglint_oiio.so: every image read and write through OpenImageIO, loaded by libglint on
/// first use (image_codec.h says why). Nothing here throws across the boundary.

#include "image_codec.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <memory>

namespace {

using glint::codec::DecodedImage;
using glint::codec::kAttributePrefix;
using glint::codec::PixelsToWrite;
using glint::codec::SizeCheck;

/// Pixels of an opened image as floats, with what the header says about them.
std::string read_pixels(OIIO::ImageInput& input, const SizeCheck& check, DecodedImage& out) {
    const OIIO::ImageSpec& spec = input.spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) return "image has no pixels";
    if (std::string refused = check(spec.width, spec.height, spec.nchannels); !refused.empty()) return refused;
    out.width = spec.width;
    out.height = spec.height;
    out.channels = spec.nchannels;
    out.pixels.assign(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels), 0.0f);
    if (!input.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.pixels.data()))
        return "cannot read image: " + input.geterror();
    input.close();
    out.channel_names.assign(spec.channelnames.begin(), spec.channelnames.end());
    out.integer_data =
        !(spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
          spec.format.basetype == OIIO::TypeDesc::DOUBLE);
    const std::string color_space = spec.get_string_attribute("oiio:ColorSpace");
    out.linear_tagged = color_space == "Linear" || color_space == "linear";
    out.alpha_channel = spec.alpha_channel;
    if (spec.x != spec.full_x || spec.y != spec.full_y || spec.width != spec.full_width ||
        spec.height != spec.full_height) {
        out.x = spec.x - spec.full_x;
        out.y = spec.y - spec.full_y;
        out.frame_width = spec.full_width;
        out.frame_height = spec.full_height;
    }
    for (const OIIO::ParamValue& attribute : spec.extra_attribs) {
        const std::string name = attribute.name().string();
        if (name.rfind(kAttributePrefix, 0) == 0 && attribute.type() == OIIO::TypeDesc::STRING)
            out.attributes.emplace_back(name.substr(kAttributePrefix.size()), attribute.get_string());
    }
    return "";
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

/// `body()`, with any exception (std::bad_alloc above all) turned into its message.
template <typename Body>
std::string guarded(Body&& body) {
    try {
        return body();
    } catch (const std::exception& e) {
        return std::string("cannot read image: ") + e.what();
    }
}

std::string read_file(const std::string& path, const SizeCheck& check, DecodedImage& out) {
    return guarded([&] {
        const OIIO::ImageSpec config = straight_alpha_config();
        auto input = OIIO::ImageInput::open(path, &config);
        if (!input) return "cannot read image: " + OIIO::geterror();
        return read_pixels(*input, check, out);
    });
}

std::string read_memory(const unsigned char* bytes, std::size_t size, const std::string& name, const SizeCheck& check,
                        DecodedImage& out) {
    return guarded([&] {
        // OpenImageIO picks the reader from the name's extension and falls back to sniffing the
        // bytes. In 2.4 a reader opened with a config spec takes the proxy from the spec's
        // "oiio:ioproxy" attribute (a pointer to the pointer), not only from the argument.
        BoundedMemoryReader reader(bytes, size);
        OIIO::Filesystem::IOProxy* proxy = &reader;
        OIIO::ImageSpec config = straight_alpha_config();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        auto input = OIIO::ImageInput::open(name, &config, &reader);
        if (!input) return "cannot decode image: " + OIIO::geterror();
        return read_pixels(*input, check, out);
    });
}

std::string write_file(const std::string& format_name, const std::string& file, const PixelsToWrite& pixels) {
    try {
        auto output = OIIO::ImageOutput::create(format_name);
        if (!output) return "cannot create a writer: " + OIIO::geterror();
        OIIO::ImageSpec spec(pixels.width, pixels.height, pixels.channels,
                             pixels.floats ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
        if (pixels.channel_names) {
            spec.channelnames = *pixels.channel_names;
            spec.alpha_channel = -1;  // no channel is coverage: a fourth one is a count or an AOV
        }
        spec.attribute("oiio:ColorSpace", pixels.floats ? "Linear" : "sRGB");
        spec.attribute("Software", "Glint");
        if (pixels.frame_width > 0) {
            spec.x = pixels.x;
            spec.y = pixels.y;
            spec.full_x = spec.full_y = 0;
            spec.full_width = pixels.frame_width;
            spec.full_height = pixels.frame_height;
        }
        if (pixels.attributes)
            for (const auto& [name, text] : *pixels.attributes) spec.attribute(kAttributePrefix + name, text);
        if (!(output->open(file, spec) && output->write_image(OIIO::TypeDesc::FLOAT, pixels.data) && output->close()))
            return "cannot write image: " + output->geterror();
        return "";
    } catch (const std::exception& e) {
        return std::string("cannot write image: ") + e.what();
    }
}

constexpr glint::codec::Functions kFunctions{read_file, read_memory, write_file};

}  // namespace

extern "C" __attribute__((visibility("default"))) const glint::codec::Functions* glint_oiio_codec() {
    return &kFunctions;
}
