#pragma once
/// \file A render shown as it happens: the finished tiles of a film streamed to a display
/// server (tev's protocol, io/tev_protocol.h), as pbrt-v4's --display-server does.
///
/// A background thread wakes every kPeriod, connects if it is not connected (sending
/// CreateImage, and then every finished tile again: the viewer may have restarted), and
/// sends the tiles finished since its last pass, one UpdateImage each. It only reads the
/// film, and only tiles the TileGrid marks done, whose pixels no worker writes any more. The
/// render never waits for the viewer beyond the connection's timeouts and never fails for
/// it: the first failure to connect is one warning, and the stream keeps retrying quietly.

#include "glint/image/film.h"
#include "glint/integrators/tile_grid.h"
#include "glint/io/display_connection.h"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace glint {

class FilmStream {
public:
    /// About four updates a second, as pbrt-v4 and tev's own examples send.
    static constexpr std::chrono::milliseconds kPeriod{250};

    /// Start streaming `film` (whose tiles `tiles` tracks) to `address` as image `name`.
    /// `warn` receives the one warning line, from the stream's thread.
    FilmStream(const DisplayAddress& address, std::string name, const Film& film, const TileGrid& tiles,
               std::function<void(const std::string&)> warn);
    /// Finishes the stream (see finish()).
    ~FilmStream();
    FilmStream(const FilmStream&) = delete;
    FilmStream& operator=(const FilmStream&) = delete;

    /// One last pass, for the tiles finished since the last, then close the connection and
    /// stop the thread. Call it when the render is over.
    void finish();

private:
    void run();
    /// Connect if needed and send the finished tiles not yet sent.
    void pass();
    bool send_tile(uint32_t tile);

    DisplayConnection connection_;
    std::string name_;
    const Film& film_;
    const TileGrid& tiles_;
    std::function<void(const std::string&)> warn_;
    std::vector<bool> sent_;
    bool warned_ = false;

    std::mutex mutex_;
    std::condition_variable wake_;
    bool finishing_ = false;
    std::thread thread_;
};

}  // namespace glint
