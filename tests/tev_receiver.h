#pragma once
// A display server for tests, since tev is not in Debian: it listens on a free loopback
// port, takes connections one after another, parses the packets of tev's protocol as tev
// does (../shared/docs/tev-protocol.md) and rebuilds the images they describe.

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace glint_test {

struct ReceivedImage {
    int32_t width = 0, height = 0;
    std::vector<std::string> channels;
    /// Interleaved values, NaN where no update reached.
    std::vector<float> values;
    std::size_t updates = 0;
};

/// What a viewer holds after a run of packets.
struct ViewerState {
    std::map<std::string, ReceivedImage> images;
    int connections = 0;
    /// The first packet that broke the protocol, described (empty when none did).
    std::string error;
};

/// Reads the fields of one packet in order; throws std::runtime_error past its end.
class PacketReader {
public:
    PacketReader(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    template <typename T>
    T number() {
        if (size_ - at_ < sizeof(T)) throw std::runtime_error("packet ends early");
        T v;
        std::memcpy(&v, data_ + at_, sizeof(T));
        at_ += sizeof(T);
        return v;
    }
    std::string string() {
        const void* nul = std::memchr(data_ + at_, 0, size_ - at_);
        if (!nul) throw std::runtime_error("string without NUL");
        std::string s(reinterpret_cast<const char*>(data_ + at_), static_cast<const uint8_t*>(nul) - (data_ + at_));
        at_ += s.size() + 1;
        return s;
    }
    /// The `index`th float of what is left.
    float float_at(std::size_t index) const {
        if (index >= (size_ - at_) / sizeof(float)) throw std::runtime_error("update data ends early");
        float v;
        std::memcpy(&v, data_ + at_ + index * sizeof(float), sizeof(float));
        return v;
    }

private:
    const uint8_t* data_;
    std::size_t size_, at_ = 0;
};

/// Apply one packet (without its length prefix) to `state`, as tev would. Throws
/// std::runtime_error on a malformed packet.
inline void apply_tev_packet(const uint8_t* data, std::size_t size, ViewerState& state) {
    PacketReader in(data, size);
    auto i32 = [&] { return in.number<int32_t>(); };
    const auto type = in.number<uint8_t>();
    if (type == 4) {                 // CreateImage
        (void)in.number<uint8_t>();  // grab focus
        ReceivedImage image;
        const std::string name = in.string();
        image.width = i32();
        image.height = i32();
        const int32_t n = i32();
        for (int32_t c = 0; c < n; ++c) image.channels.push_back(in.string());
        image.values.assign(std::size_t(image.width) * image.height * n, std::numeric_limits<float>::quiet_NaN());
        state.images[name] = std::move(image);
    } else if (type == 6) {          // UpdateImageV3
        (void)in.number<uint8_t>();  // grab focus
        const std::string name = in.string();
        const int32_t n = i32();
        std::vector<std::string> channels;
        for (int32_t c = 0; c < n; ++c) channels.push_back(in.string());
        const int32_t x = i32(), y = i32(), w = i32(), h = i32();
        std::vector<int64_t> offsets, strides;
        for (int32_t c = 0; c < n; ++c) offsets.push_back(in.number<int64_t>());
        for (int32_t c = 0; c < n; ++c) strides.push_back(in.number<int64_t>());
        const auto it = state.images.find(name);
        if (it == state.images.end()) throw std::runtime_error("update of image '" + name + "' before CreateImage");
        ReceivedImage& image = it->second;
        if (channels != image.channels) throw std::runtime_error("update with other channels");
        if (x < 0 || y < 0 || w <= 0 || h <= 0 || x + w > image.width || y + h > image.height)
            throw std::runtime_error("update outside the image");
        for (int32_t c = 0; c < n; ++c)
            for (int32_t p = 0; p < w * h; ++p) {
                const float v = in.float_at(std::size_t(offsets[c] + int64_t(p) * strides[c]));
                const std::size_t pixel = std::size_t(y + p / w) * image.width + (x + p % w);
                image.values[pixel * n + c] = v;
            }
        ++image.updates;
    } else {
        throw std::runtime_error("unexpected packet type " + std::to_string(type));
    }
}

class TevReceiver {
public:
    /// `drop_after_create`: close the first connection right after its first CreateImage (a
    /// viewer that quits), resetting it, to see the sender reconnect.
    explicit TevReceiver(bool drop_after_create = false) : drop_first_(drop_after_create) {
        listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof(address);
        if (listener_ < 0 || ::bind(listener_, reinterpret_cast<sockaddr*>(&address), length) != 0 ||
            ::listen(listener_, 5) != 0 ||
            ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length) != 0)
            throw std::runtime_error(std::string("test receiver: ") + std::strerror(errno));
        port_ = ntohs(address.sin_port);
        thread_ = std::thread([this] { serve(); });
    }
    ~TevReceiver() {
        stop_ = true;
        thread_.join();
        ::close(listener_);
    }

    [[nodiscard]] uint16_t port() const { return port_; }

    /// A copy of what the viewer holds now.
    [[nodiscard]] ViewerState state() const {
        const std::lock_guard lock(mutex_);
        return state_;
    }

    /// Wait (up to `timeout`) until `done` holds for the viewer's state.
    bool wait_for(const std::function<bool(const ViewerState&)>& done,
                  std::chrono::milliseconds timeout = std::chrono::seconds(20)) const {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < end) {
            if (done(state())) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return done(state());
    }

private:
    /// Block until `fd` is readable or the receiver stops; false when it stops.
    bool readable(int fd) const {
        pollfd p{.fd = fd, .events = POLLIN, .revents = 0};
        while (!stop_)
            if (::poll(&p, 1, 20) > 0) return true;
        return false;
    }

    void serve() {
        while (readable(listener_)) {
            const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
            if (fd < 0) continue;
            int connection;
            {
                const std::lock_guard lock(mutex_);
                connection = ++state_.connections;
            }
            read_packets(fd, connection == 1 && drop_first_);
            ::close(fd);
        }
    }

    /// Read packets from `fd` until it closes; with `drop`, reset it after a CreateImage.
    void read_packets(int fd, bool drop) {
        std::vector<uint8_t> buffer;
        uint8_t chunk[65536];
        while (readable(fd)) {
            const ssize_t n = ::recv(fd, chunk, sizeof(chunk), 0);
            if (n <= 0) return;
            buffer.insert(buffer.end(), chunk, chunk + n);
            std::size_t used = 0;
            while (buffer.size() - used >= 4) {
                uint32_t length;
                std::memcpy(&length, buffer.data() + used, 4);
                if (length < 5) return fail("packet length " + std::to_string(length));
                if (buffer.size() - used < length) break;
                const uint8_t type = buffer[used + 4];
                {
                    const std::lock_guard lock(mutex_);
                    try {
                        apply_tev_packet(buffer.data() + used + 4, length - 4, state_);
                    } catch (const std::exception& e) {
                        if (state_.error.empty()) state_.error = e.what();
                        return;
                    }
                }
                used += length;
                if (drop && type == 4) {
                    const linger reset{.l_onoff = 1, .l_linger = 0};  // close with RST, as a killed viewer
                    ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof(reset));
                    return;
                }
            }
            buffer.erase(buffer.begin(), buffer.begin() + std::ptrdiff_t(used));
        }
    }

    void fail(const std::string& why) {
        const std::lock_guard lock(mutex_);
        if (state_.error.empty()) state_.error = why;
    }

    bool drop_first_;
    int listener_ = -1;
    uint16_t port_ = 0;
    std::atomic<bool> stop_{false};
    mutable std::mutex mutex_;
    ViewerState state_;
    std::thread thread_;
};

}  // namespace glint_test
