#include "glint/io/display_connection.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace glint {

namespace {

[[noreturn]] void bad_address(std::string_view text, std::string_view why) {
    throw std::invalid_argument("expected HOST:PORT, such as 127.0.0.1:14158 or [::1]:14158 (" + std::string(why) +
                                "); got '" + std::string(text) + "'");
}

/// A connected socket to `address` or -1, within kConnectTimeoutMs; `error` says why not.
int connect_with_timeout(const addrinfo& address, int timeout_ms, std::string& error) {
    const int fd = ::socket(address.ai_family, address.ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, address.ai_protocol);
    if (fd < 0) {
        error = std::strerror(errno);
        return -1;
    }
    int status = ::connect(fd, address.ai_addr, address.ai_addrlen);
    if (status != 0 && errno == EINPROGRESS) {
        pollfd waiting{.fd = fd, .events = POLLOUT, .revents = 0};
        int ready;
        do ready = ::poll(&waiting, 1, timeout_ms);
        while (ready < 0 && errno == EINTR);
        if (ready == 0) {
            errno = ETIMEDOUT;
        } else if (ready > 0) {
            int so_error = 0;
            socklen_t length = sizeof(so_error);
            ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &so_error, &length);
            errno = so_error;
            status = so_error == 0 ? 0 : -1;
        }
    }
    if (status != 0) {
        error = std::strerror(errno);
        ::close(fd);
        return -1;
    }
    // From here on writes block, each for at most kSendTimeoutMs.
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    const timeval send_timeout{.tv_sec = DisplayConnection::kSendTimeoutMs / 1000,
                               .tv_usec = DisplayConnection::kSendTimeoutMs % 1000 * 1000};
    ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &send_timeout, sizeof(send_timeout));
    const int on = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
    return fd;
}

}  // namespace

std::string DisplayAddress::text() const {
    const std::string shown = host.find(':') != std::string::npos ? "[" + host + "]" : host;
    return shown + ":" + std::to_string(port);
}

DisplayAddress parse_display_address(std::string_view text) {
    const std::size_t colon = text.rfind(':');
    if (colon == std::string_view::npos) bad_address(text, "no port");
    std::string_view host = text.substr(0, colon);
    const std::string_view port_text = text.substr(colon + 1);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
        host = host.substr(1, host.size() - 2);
    } else if (host.find(':') != std::string_view::npos) {
        bad_address(text, "an IPv6 address goes in brackets");
    }
    if (host.empty()) bad_address(text, "no host");
    unsigned port = 0;
    const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
    if (port_text.empty() || ec != std::errc() || end != port_text.data() + port_text.size() || port == 0 ||
        port > 65535)
        bad_address(text, "the port is a number from 1 to 65535");
    return {std::string(host), static_cast<uint16_t>(port)};
}

std::string DisplayConnection::connect() {
    if (connected()) return {};
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const int lookup = ::getaddrinfo(address_.host.c_str(), std::to_string(address_.port).c_str(), &hints, &found);
    if (lookup != 0) return ::gai_strerror(lookup);
    const std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)> addresses(found, &::freeaddrinfo);
    std::string error = "no address";
    for (const addrinfo* a = found; a && socket_ < 0; a = a->ai_next)
        socket_ = connect_with_timeout(*a, kConnectTimeoutMs, error);
    return connected() ? std::string() : error;
}

bool DisplayConnection::send(std::span<const uint8_t> bytes) {
    while (connected() && !bytes.empty()) {
        const ssize_t sent = ::send(socket_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR) continue;
        if (sent <= 0)
            disconnect();  // closed, reset or timed out: the next pass reconnects
        else
            bytes = bytes.subspan(std::size_t(sent));
    }
    return connected();
}

void DisplayConnection::disconnect() {
    if (socket_ >= 0) ::close(socket_);
    socket_ = -1;
}

}  // namespace glint
