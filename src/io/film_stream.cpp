#include "glint/io/film_stream.h"

#include "glint/io/tev_protocol.h"

#include <algorithm>
#include <array>

namespace glint {

namespace {

/// Linear radiance, as the EXR output holds it; the viewer applies its own exposure.
const std::array<std::string, 3> kChannels = {"R", "G", "B"};

}  // namespace

FilmStream::FilmStream(const DisplayAddress& address, std::string name, const Film& film, const TileGrid& tiles,
                       std::function<void(const std::string&)> warn)
    : connection_(address),
      name_(std::move(name)),
      film_(film),
      tiles_(tiles),
      warn_(std::move(warn)),
      sent_(tiles.count(), false),
      thread_([this] { run(); }) {}

FilmStream::~FilmStream() { finish(); }

void FilmStream::finish() {
    {
        const std::lock_guard lock(mutex_);
        if (finishing_) return;
        finishing_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void FilmStream::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        const bool last = wake_.wait_for(lock, kPeriod, [this] { return finishing_; });
        lock.unlock();
        pass();
        lock.lock();
        if (last) break;
    }
    connection_.disconnect();
}

void FilmStream::pass() {
    if (!connection_.connected()) {
        const std::string error = connection_.connect();
        if (!error.empty()) {
            if (!warned_)
                warn_("display server " + connection_.address().text() + ": cannot connect (" + error +
                      "); the render goes on without it and keeps trying");
            warned_ = true;
            return;
        }
        // A new connection, perhaps to a restarted viewer: it has none of the image.
        std::fill(sent_.begin(), sent_.end(), false);
        const auto create = tev::create_image(name_, int32_t(film_.width()), int32_t(film_.height()), kChannels, true);
        if (!connection_.send(create)) return;
    }
    for (uint32_t tile = 0; tile < tiles_.count(); ++tile) {
        if (sent_[tile] || !tiles_.done(tile)) continue;
        if (!send_tile(tile)) return;  // disconnected: the next pass starts over
        sent_[tile] = true;
    }
}

bool FilmStream::send_tile(uint32_t tile) {
    const TileGrid::Bounds b = tiles_.bounds(tile);
    std::vector<float> values;
    values.reserve(std::size_t(b.x1 - b.x0) * (b.y1 - b.y0) * kChannels.size());
    for (uint32_t y = b.y0; y < b.y1; ++y)
        for (uint32_t x = b.x0; x < b.x1; ++x) {
            const Color c = film_.at(x, y);
            values.insert(values.end(), {c.r, c.g, c.b});
        }
    return connection_.send(tev::update_image(name_, kChannels, int32_t(b.x0), int32_t(b.y0), int32_t(b.x1 - b.x0),
                                              int32_t(b.y1 - b.y0), values));
}

}  // namespace glint
