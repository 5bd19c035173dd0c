#pragma once
/// \file A TCP connection to a display server (an HDR viewer such as tev) that a render
/// writes to and never waits on for long: connecting and sending time out, a viewer that
/// closes or restarts costs one failed send, and no write raises SIGPIPE.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace glint {

/// Where a display server listens.
struct DisplayAddress {
    std::string host;
    uint16_t port = 0;
    /// "host:port", or "[host]:port" for an IPv6 literal.
    [[nodiscard]] std::string text() const;
};

/// Parse "HOST:PORT" or "[IPv6]:PORT" (tev listens on 127.0.0.1:14158). Throws
/// std::invalid_argument saying what was expected; the host is looked up only when connecting.
[[nodiscard]] DisplayAddress parse_display_address(std::string_view text);

class DisplayConnection {
public:
    /// How long connecting may take, and one send (as pbrt-v4 allows).
    static constexpr int kConnectTimeoutMs = 1000;
    static constexpr int kSendTimeoutMs = 3000;

    explicit DisplayConnection(DisplayAddress address) : address_(std::move(address)) {}
    ~DisplayConnection() { disconnect(); }
    DisplayConnection(const DisplayConnection&) = delete;
    DisplayConnection& operator=(const DisplayConnection&) = delete;

    [[nodiscard]] const DisplayAddress& address() const { return address_; }
    [[nodiscard]] bool connected() const { return socket_ >= 0; }
    /// Connect unless connected. Returns an empty string, or why it could not.
    [[nodiscard]] std::string connect();
    /// Send all of `bytes`. On failure the connection is closed and false returned.
    bool send(std::span<const uint8_t> bytes);
    void disconnect();

private:
    DisplayAddress address_;
    int socket_ = -1;
};

}  // namespace glint
