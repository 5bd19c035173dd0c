#pragma once
/// \file The packets of tev's display-server protocol (Tom94/tev, src/Ipc.cpp), which HDR
/// viewers speak to show a render as it happens: pbrt-v4's --display-server sends them too.
///
/// Every packet is [uint32 total length, these 4 bytes included][uint8 type][payload], all
/// little-endian; a string is its bytes and one NUL. tev never answers.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint::tev {

/// Packet types Glint sends (tev's IpcPacket::Type).
enum class PacketType : uint8_t {
    CreateImage = 4,
    UpdateImageV3 = 6,
};

/// CreateImage: a `width`×`height` image called `name` with these channels, replacing an image
/// of that name. `grab_focus` brings it to the front.
[[nodiscard]] std::vector<uint8_t> create_image(std::string_view name, int32_t width, int32_t height,
                                                std::span<const std::string> channels, bool grab_focus);

/// UpdateImageV3: the rectangle (x, y, width, height) of image `name`, its `channels`
/// interleaved pixel by pixel, rows from the top (values.size() = width·height·channels).
[[nodiscard]] std::vector<uint8_t> update_image(std::string_view name, std::span<const std::string> channels, int32_t x,
                                                int32_t y, int32_t width, int32_t height,
                                                std::span<const float> values);

}  // namespace glint::tev
