#include "glint/io/tev_protocol.h"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace glint::tev {

namespace {

static_assert(std::endian::native == std::endian::little, "tev packets are little-endian, as this machine is");

/// A packet being written: a placeholder for its length, then its type and payload.
class PacketWriter {
public:
    explicit PacketWriter(PacketType type) {
        bytes_.resize(sizeof(uint32_t));
        bytes_.push_back(static_cast<uint8_t>(type));
    }
    void boolean(bool value) { bytes_.push_back(value ? 1 : 0); }
    void string(std::string_view text) {
        // A NUL inside would end the string early on the viewer's side and shift the rest.
        if (text.find('\0') != std::string_view::npos)
            throw std::invalid_argument("tev: a name or channel with a NUL byte cannot be sent");
        bytes_.insert(bytes_.end(), text.begin(), text.end());
        bytes_.push_back(0);
    }
    template <typename T>
    void value(T v) {
        const std::size_t at = bytes_.size();
        bytes_.resize(at + sizeof(T));
        std::memcpy(bytes_.data() + at, &v, sizeof(T));
    }
    void floats(std::span<const float> values) {
        const std::size_t at = bytes_.size();
        bytes_.resize(at + values.size_bytes());
        std::memcpy(bytes_.data() + at, values.data(), values.size_bytes());
    }
    /// The finished packet, its length filled in.
    std::vector<uint8_t> finish() && {
        if (bytes_.size() > UINT32_MAX) throw std::invalid_argument("tev: a packet must stay under 4 GiB");
        const auto length = static_cast<uint32_t>(bytes_.size());
        std::memcpy(bytes_.data(), &length, sizeof(length));
        return std::move(bytes_);
    }

private:
    std::vector<uint8_t> bytes_;
};

}  // namespace

std::vector<uint8_t> create_image(std::string_view name, int32_t width, int32_t height,
                                  std::span<const std::string> channels, bool grab_focus) {
    PacketWriter packet(PacketType::CreateImage);
    packet.boolean(grab_focus);
    packet.string(name);
    packet.value(width);
    packet.value(height);
    packet.value(static_cast<int32_t>(channels.size()));
    for (const std::string& channel : channels) packet.string(channel);
    return std::move(packet).finish();
}

std::vector<uint8_t> update_image(std::string_view name, std::span<const std::string> channels, int32_t x, int32_t y,
                                  int32_t width, int32_t height, std::span<const float> values) {
    const std::size_t n = channels.size();
    if (values.size() != std::size_t(width) * std::size_t(height) * n)
        throw std::invalid_argument("tev: an update needs width × height × channels values");
    PacketWriter packet(PacketType::UpdateImageV3);
    packet.boolean(false);
    packet.string(name);
    packet.value(static_cast<int32_t>(n));
    for (const std::string& channel : channels) packet.string(channel);
    for (int32_t v : {x, y, width, height}) packet.value(v);
    // Interleaved: channel c of pixel p is values[c + p·n].
    for (std::size_t c = 0; c < n; ++c) packet.value(static_cast<int64_t>(c));
    for (std::size_t c = 0; c < n; ++c) packet.value(static_cast<int64_t>(n));
    packet.floats(values);
    return std::move(packet).finish();
}

}  // namespace glint::tev
