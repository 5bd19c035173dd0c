/// libglint_exr.so: OpenEXR output through OpenEXR itself, loaded by libglint on the first
/// EXR written or read (image_codec.h says why a module; input is exr_reader.cpp). Nothing
/// here throws across the boundary.
///
/// The file is what OpenImageIO's writer made of the same pixels: 32-bit float channels, ZIP
/// compression at OpenEXR's default level, R G B (one channel: Y) unless named, the data
/// window inside the display window, "Software" and the "glint:NAME" text attributes. It
/// carries no "DateTime", so the same render gives the same bytes.

#include "exr_reader.h"
#include "image_codec.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>

#include <exception>
#include <string>
#include <vector>

namespace {

using glint::codec::PixelsToWrite;

/// OpenImageIO's names for channels without names of their own: Y for one, else R G B A.
std::vector<std::string> channel_names(const PixelsToWrite& pixels) {
    if (pixels.channel_names) return *pixels.channel_names;
    if (pixels.channels == 1) return {"Y"};
    static const char* const kRgba[] = {"R", "G", "B", "A"};
    return {kRgba, kRgba + pixels.channels};
}

std::string write_file(const std::string& file, const PixelsToWrite& pixels) {
    try {
        if (!pixels.floats || pixels.channels < 1 || (!pixels.channel_names && pixels.channels > 4))
            return "cannot write image: EXR output takes float pixels with names for more than four channels";
        // ZIP compresses 16 rows at a time, in parallel on OpenEXR's own pool: 46 ms for a
        // 640×480 render on two threads, 71 ms on one. Resized only when asked for another count.
        if (pixels.threads != Imf::globalThreadCount()) Imf::setGlobalThreadCount(pixels.threads);

        const Imath::Box2i data_window(Imath::V2i(pixels.x, pixels.y),
                                       Imath::V2i(pixels.x + pixels.width - 1, pixels.y + pixels.height - 1));
        const Imath::Box2i display_window =
            pixels.frame_width > 0
                ? Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(pixels.frame_width - 1, pixels.frame_height - 1))
                : data_window;
        Imf::Header header(display_window, data_window);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.insert("Software", Imf::StringAttribute("Glint"));
        if (pixels.attributes)
            for (const auto& [name, text] : *pixels.attributes)
                header.insert(glint::codec::kAttributePrefix + name, Imf::StringAttribute(text));

        Imf::FrameBuffer frame;
        const std::vector<std::string> names = channel_names(pixels);
        const std::size_t pixel_stride = sizeof(float) * std::size_t(pixels.channels);
        for (int c = 0; c < pixels.channels; ++c) {
            header.channels().insert(names[std::size_t(c)], Imf::Channel(Imf::FLOAT));
            frame.insert(names[std::size_t(c)], Imf::Slice::Make(Imf::FLOAT, pixels.data + c, data_window, pixel_stride,
                                                                 pixel_stride * pixels.width));
        }
        Imf::OutputFile output(file.c_str(), header, pixels.threads);
        output.setFrameBuffer(frame);
        output.writePixels(pixels.height);
        return "";
    } catch (const std::exception& e) {
        return std::string("cannot write image: ") + e.what();
    }
}

constexpr glint::codec::ExrFunctions kFunctions{write_file, glint::codec::read_exr};

}  // namespace

extern "C" __attribute__((visibility("default"))) const glint::codec::ExrFunctions* glint_exr_codec() {
    return &kFunctions;
}
