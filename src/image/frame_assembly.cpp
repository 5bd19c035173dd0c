#include "glint/image/frame_assembly.h"

#include "glint/image/image_io.h"
#include "glint/util/named_values.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace glint {

namespace {

struct FrameSize {
    int width = 0, height = 0;
    bool operator==(const FrameSize&) const = default;
};

FrameSize frame_size(const Image& part) {
    return part.region.whole() ? FrameSize{part.width, part.height}
                               : FrameSize{part.region.frame_width, part.region.frame_height};
}

std::string channel_list(const Image& image) {
    std::string list;
    for (const std::string& name : image.channel_names) list += (list.empty() ? "" : ", ") + name;
    return list.empty() ? fmt::format("{} unnamed channels", image.channels) : list;
}

/// The first attribute in which `a` and `b` differ, in words; empty if none.
std::string attribute_difference(const FramePart& a, const FramePart& b) {
    const auto differences = named_value_differences(a.image.attributes, b.image.attributes);
    if (differences.empty()) return {};
    const auto& [name, va, vb] = differences.front();
    return fmt::format("{}: {} in {}, {} in {}", name, va, a.name, vb, b.name);
}

}  // namespace

Image crop_of(const Image& frame, int x0, int y0, int x1, int y1) {
    Image crop(x1 - x0, y1 - y0, frame.channels);
    const auto row = std::size_t(crop.width) * std::size_t(frame.channels);
    for (int y = y0; y < y1; ++y)
        std::copy_n(&frame.pixels[(std::size_t(y) * frame.width + std::size_t(x0)) * frame.channels], row,
                    &crop.pixels[std::size_t(y - y0) * row]);
    crop.channel_names = frame.channel_names;
    crop.attributes = frame.attributes;
    crop.region = {x0, y0, frame.width, frame.height};
    return crop;
}

Image assemble_frame(std::span<const FramePart> parts) {
    if (parts.empty()) throw ImageError("nothing to assemble");
    const FramePart& first = parts.front();
    const FrameSize size = frame_size(first.image);
    for (const FramePart& part : parts) {
        if (part.image.region.whole() && parts.size() > 1)
            throw ImageError(
                fmt::format("{} is a whole frame, not a crop of one (only an EXR written by glint render "
                            "--crop keeps its place in the frame)",
                            part.name));
        if (frame_size(part.image) != size)
            throw ImageError(fmt::format("{} is part of a {}×{} frame, {} of a {}×{} one", part.name,
                                         frame_size(part.image).width, frame_size(part.image).height, first.name,
                                         size.width, size.height));
        if (part.image.channel_names != first.image.channel_names || part.image.channels != first.image.channels)
            throw ImageError(fmt::format("{} has the channels {}, {} has {}", part.name, channel_list(part.image),
                                         first.name, channel_list(first.image)));
        if (const std::string difference = attribute_difference(first, part); !difference.empty())
            throw ImageError(
                fmt::format("{} and {} come from different renders ({})", first.name, part.name, difference));
        const FrameRegion& r = part.image.region;
        if (r.x < 0 || r.y < 0 || r.x + part.image.width > size.width || r.y + part.image.height > size.height)
            throw ImageError(fmt::format("{}: its pixels [{}, {}) × [{}, {}) reach past its {}×{} frame", part.name,
                                         r.x, r.x + part.image.width, r.y, r.y + part.image.height, size.width,
                                         size.height));
    }
    // Which part each pixel came from: an overlap or a gap is found where it is.
    constexpr int32_t kNone = -1;
    std::vector<int32_t> owner(std::size_t(size.width) * std::size_t(size.height), kNone);
    Image frame(size.width, size.height, first.image.channels);
    frame.channel_names = first.image.channel_names;
    frame.attributes = first.image.attributes;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Image& part = parts[p].image;
        for (int y = 0; y < part.height; ++y)
            for (int x = 0; x < part.width; ++x) {
                const int fx = part.region.x + x, fy = part.region.y + y;
                int32_t& o = owner[std::size_t(fy) * std::size_t(size.width) + std::size_t(fx)];
                if (o != kNone)
                    throw ImageError(fmt::format("{} and {} overlap (both hold pixel ({}, {}))",
                                                 parts[std::size_t(o)].name, parts[p].name, fx, fy));
                o = int32_t(p);
                std::copy_n(&part.pixels[(std::size_t(y) * part.width + std::size_t(x)) * part.channels], part.channels,
                            &frame.pixels[(std::size_t(fy) * size.width + std::size_t(fx)) * part.channels]);
            }
    }
    if (const auto gap = std::find(owner.begin(), owner.end(), kNone); gap != owner.end()) {
        const auto missing = std::count(owner.begin(), owner.end(), kNone);
        const auto index = std::size_t(gap - owner.begin());
        throw ImageError(fmt::format("the parts leave {} of the frame's {}×{} pixels uncovered, the first at ({}, {})",
                                     missing, size.width, size.height, index % std::size_t(size.width),
                                     index / std::size_t(size.width)));
    }
    return frame;
}

}  // namespace glint
