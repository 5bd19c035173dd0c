/// Part of libglint_exr.so: EXR input through OpenEXR alone (exr_reader.h says why and what
/// is left to OpenImageIO). Nothing here throws: OpenEXR's exceptions hand the file on.

#include "exr_reader.h"

#include "glint/util/byte_order.h"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfEnvmapAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <ImfVersion.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string_view>
#include <vector>

namespace glint::codec {

namespace {

/// The file's bytes as OpenEXR reads a stream; a read past the end throws, as a file's would.
class MemoryStream final : public Imf::IStream {
public:
    MemoryStream(const unsigned char* bytes, std::size_t size) : Imf::IStream("memory"), bytes_(bytes), size_(size) {}

    bool read(char out[], int n) override {
        if (n < 0 || position_ > size_ || uint64_t(n) > size_ - position_)
            throw Iex::InputExc("Unexpected end of file.");
        std::memcpy(out, bytes_ + position_, std::size_t(n));
        position_ += uint64_t(n);
        return position_ < size_;
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override { position_ = position; }

private:
    const unsigned char* bytes_;
    uint64_t size_;
    uint64_t position_ = 0;
};

bool equal_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

/// A channel's name split at its last dot into layer ("diffuse.", or "") and suffix ("R"),
/// which is how OpenImageIO orders a file's channels: by layer, then known suffixes first in
/// the order of a list (any case), then the rest by name.
struct ChannelName {
    std::string full;
    std::size_t suffix_start = 0;  // past the last dot
    int rank = 0;

    explicit ChannelName(std::string name) : full(std::move(name)) {
        const std::size_t dot = full.find_last_of('.');
        suffix_start = dot == std::string::npos ? 0 : dot + 1;
    }
    std::string_view layer() const { return std::string_view(full).substr(0, suffix_start); }
    std::string_view suffix() const { return std::string_view(full).substr(suffix_start); }

    /// The suffix's place in OpenImageIO's list of known suffixes: one list for colour, and
    /// another, with X Y Z together, for a layer that holds X and Y or Z (a position or a
    /// normal).
    void rank_in_layer(bool vector_layer) {
        static constexpr std::array<std::string_view, 20> kColour = {
            "R",     "Red", "G",  "Green", "B",  "Blue", "Y",  "real", "imag",  "A",
            "Alpha", "AR",  "RA", "AG",    "GA", "AB",   "BA", "Z",    "Depth", "Zback"};
        static constexpr std::array<std::string_view, 21> kVector = {
            "R", "Red",   "G",  "Green", "B",  "Blue", "X",  "Y",  "Z",     "real", "imag",
            "A", "Alpha", "AR", "RA",    "AG", "GA",   "AB", "BA", "Depth", "Zback"};
        const auto place = [&](const auto& known) {
            const auto found = std::find_if(known.begin(), known.end(),
                                            [&](std::string_view k) { return equal_ignoring_case(suffix(), k); });
            return int(found - known.begin());  // past the list when unknown
        };
        rank = vector_layer ? place(kVector) : place(kColour);
    }

    bool operator<(const ChannelName& other) const {
        if (layer() != other.layer()) return layer() < other.layer();
        if (rank != other.rank) return rank < other.rank;
        return suffix() < other.suffix();
    }
    bool is(std::string_view name) const { return equal_ignoring_case(suffix(), name); }
};

/// The file's channels in OpenImageIO's order.
void order_as_openimageio_does(std::vector<ChannelName>& names) {
    std::stable_sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.layer() < b.layer(); });
    for (auto begin = names.begin(); begin != names.end();) {
        const auto end = std::find_if(begin, names.end(), [&](const auto& n) { return n.layer() != begin->layer(); });
        const auto holds = [&](std::string_view suffix) {
            return std::any_of(begin, end, [&](const auto& n) { return n.is(suffix); });
        };
        const bool vector_layer = holds("X") && (holds("Y") || holds("Z"));
        for (auto n = begin; n != end; ++n) n->rank_in_layer(vector_layer);
        begin = end;
    }
    std::stable_sort(names.begin(), names.end());
}

/// A window's side, or 0 when the window is empty or wider than an int.
int side(int min, int max) {
    const int64_t length = int64_t(max) - int64_t(min) + 1;
    return length > 0 && length <= INT_MAX ? int(length) : 0;
}

}  // namespace

std::optional<std::string> read_exr(const unsigned char* bytes, std::size_t size, const SizeCheck& check, int threads,
                                    DecodedImage& out) {
    if (size < 8 || !is_exr(bytes, size)) return std::nullopt;
    int version = int(little_endian_u32(bytes + 4));
    if (Imf::isMultiPart(version) || Imf::isNonImage(version) || !Imf::supportsFlags(Imf::getFlags(version)))
        return std::nullopt;
    try {
        MemoryStream stream(bytes, size);
        stream.seekg(8);
        Imf::Header header;
        header.readFrom(stream, version);
        const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
        const int width = side(data.min.x, data.max.x), height = side(data.min.y, data.max.y);
        const auto fits_int = [](int64_t v) { return v >= INT_MIN && v <= INT_MAX; };
        if (width == 0 || height == 0 || side(display.min.x, display.max.x) == 0 ||
            side(display.min.y, display.max.y) == 0 || !fits_int(int64_t(data.min.x) - display.min.x) ||
            !fits_int(int64_t(data.min.y) - display.min.y))
            return std::nullopt;
        // OpenImageIO frames a MIP-mapped cube map as one face; cube maps are left to it.
        const auto* envmap = header.findTypedAttribute<Imf::EnvmapAttribute>("envmap");
        if (envmap && envmap->value() == Imf::ENVMAP_CUBE) return std::nullopt;
        std::vector<ChannelName> names;
        for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel) {
            const Imf::Channel& c = channel.channel();
            if ((c.type != Imf::HALF && c.type != Imf::FLOAT) || c.xSampling != 1 || c.ySampling != 1)
                return std::nullopt;
            names.emplace_back(channel.name());
        }
        if (names.empty()) return std::nullopt;
        const int channels = int(names.size());
        if (std::string refused = check(width, height, channels); !refused.empty()) return refused;
        order_as_openimageio_does(names);

        if (threads != Imf::globalThreadCount()) Imf::setGlobalThreadCount(threads);
        stream.seekg(0);
        Imf::InputFile file(stream, threads);
        out.pixels.assign(std::size_t(width) * std::size_t(height) * std::size_t(channels), 0.0f);
        Imf::FrameBuffer frame;
        const std::size_t pixel_stride = sizeof(float) * std::size_t(channels);
        for (int c = 0; c < channels; ++c)
            frame.insert(names[std::size_t(c)].full, Imf::Slice::Make(Imf::FLOAT, out.pixels.data() + c, data,
                                                                      pixel_stride, pixel_stride * std::size_t(width)));
        file.setFrameBuffer(frame);
        file.readPixels(data.min.y, data.max.y);

        out.width = width;
        out.height = height;
        out.channels = channels;
        out.channel_names.clear();
        out.alpha_channel = -1;
        for (int c = 0; c < channels; ++c) {
            out.channel_names.push_back(names[std::size_t(c)].full);
            if (out.alpha_channel < 0 && (names[std::size_t(c)].is("A") || names[std::size_t(c)].is("Alpha")))
                out.alpha_channel = c;
        }
        out.integer_data = false;
        out.linear_tagged = true;  // OpenImageIO tags every EXR "Linear"
        if (data != display) {
            out.x = int(int64_t(data.min.x) - display.min.x);
            out.y = int(int64_t(data.min.y) - display.min.y);
            out.frame_width = side(display.min.x, display.max.x);
            out.frame_height = side(display.min.y, display.max.y);
        }
        out.attributes.clear();
        for (auto attribute = header.begin(); attribute != header.end(); ++attribute) {
            const std::string_view name = attribute.name();
            const auto* text = dynamic_cast<const Imf::StringAttribute*>(&attribute.attribute());
            if (text && name.starts_with(kAttributePrefix))
                out.attributes.emplace_back(name.substr(kAttributePrefix.size()), text->value());
        }
        return "";
    } catch (const std::exception&) {
        out = DecodedImage{};
        return std::nullopt;
    }
}

}  // namespace glint::codec
