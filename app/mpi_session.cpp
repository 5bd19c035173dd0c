// MpiSession with Open MPI, in `glint-mpi`: the work queue of tiles (mpi_session.h says why).

#include "mpi_session.h"

#include "mpi_launcher.h"

#include "glint/integrators/tile_pixels.h"
#include "glint/util/byte_stream.h"
#include "glint/util/named_values.h"

#include <fmt/core.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace glint::app {

namespace {

// Message tags: a worker asks for tiles (first time), rank 0 sends tiles (none: done), a
// worker sends finished tiles (and so asks for more).
constexpr int kRequest = 1;
constexpr int kWork = 2;
constexpr int kResult = 3;
// A batch is at most this many tiles: enough to keep a rank's threads busy.
constexpr std::size_t kMaxBatch = 32;

/// The tiles to render, handed out from the front in batches of a share of what is left
/// (guided self-scheduling, Polychronopoulos & Kuck 1987): large batches early cost few
/// messages, small ones late keep every rank busy to the end.
class TileQueue {
public:
    TileQueue(std::vector<uint32_t> order, int ranks) : order_(std::move(order)), ranks_(std::size_t(ranks)) {}

    std::vector<uint32_t> take() {
        const std::lock_guard lock(mutex_);
        const std::size_t left = order_.size() - next_;
        const std::size_t n = std::min({left, kMaxBatch, std::max<std::size_t>(1, left / (2 * ranks_))});
        std::vector<uint32_t> batch(order_.begin() + std::ptrdiff_t(next_), order_.begin() + std::ptrdiff_t(next_ + n));
        next_ += n;
        return batch;
    }

private:
    std::mutex mutex_;
    std::vector<uint32_t> order_;
    std::size_t next_ = 0;
    std::size_t ranks_;
};

/// Wait for a message from `source` with `tag` (MPI_ANY_*: any), checking `stop` and calling
/// `idle` between looks. Sleeps rather than spins: on a machine where ranks share cores, a
/// spinning wait would take a core from the rendering threads.
MPI_Status wait_for_message(int source, int tag, const MpiSession& session, const std::atomic<bool>& stop,
                            const std::function<void()>& idle = {}) {
    for (;;) {
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, &status);
        if (arrived) return status;
        if (stop.load()) session.abort("interrupted");
        if (idle) idle();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

std::string receive_bytes(const MPI_Status& status) {
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    std::string bytes(std::size_t(count), '\0');
    MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return bytes;
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
    if (!launched_by_mpi()) return;
    int provided = 0;
    // Only the main thread calls MPI; rank 0's own rendering thread never does.
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    started_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
    if (started_) MPI_Finalize();
}

void MpiSession::abort(const std::string& message) const {
    fmt::print(stderr, "glint: error: {}{}\n", distributed() ? fmt::format("rank {} of {}: ", rank_, size_) : "",
               message);
    std::fflush(stderr);
    if (started_) MPI_Abort(MPI_COMM_WORLD, 1);
    std::exit(1);
}

void MpiSession::check_same_render(const RenderFingerprint& fingerprint) const {
    if (!distributed()) return;
    ByteWriter w;
    write_named_values(w, fingerprint);
    std::string bytes = w.take();
    auto size = uint64_t(bytes.size());
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    bytes.resize(size);
    MPI_Bcast(bytes.data(), int(size), MPI_BYTE, 0, MPI_COMM_WORLD);
    if (rank_ == 0) return;
    ByteReader r(bytes);
    const auto differences = named_value_differences(read_named_values(r, UINT32_MAX), fingerprint);
    if (!differences.empty()) {
        const auto& [name, theirs, ours] = differences.front();
        abort(
            fmt::format("this rank would render another image than rank 0 ({}: {} on rank 0, {} here); every "
                        "rank needs the same scene and settings",
                        name, theirs, ours));
    }
}

RenderStats MpiSession::render(const Integrator& integrator, const RenderScene& scene, const RenderSettings& settings,
                               Film& film, AovFilm* aovs, const Integrator::ProgressCallback& progress,
                               const std::atomic<bool>& stop) const {
    if (!distributed()) return integrator.render(scene, settings, film, progress, &stop, nullptr, aovs);
    const auto start = std::chrono::steady_clock::now();
    const TileGrid grid(film.width(), film.height());
    RenderStats stats;
    if (rank_ != 0) {
        MPI_Send(nullptr, 0, MPI_BYTE, 0, kRequest, MPI_COMM_WORLD);
        for (;;) {
            const MPI_Status status = wait_for_message(0, kWork, *this, stop);
            int count = 0;
            MPI_Get_count(&status, MPI_UINT32_T, &count);
            std::vector<uint32_t> batch(static_cast<std::size_t>(count));
            MPI_Recv(batch.data(), count, MPI_UINT32_T, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (batch.empty()) break;
            const RenderStats done = integrator.render_tiles(scene, settings, film, batch, aovs);
            ByteWriter w;
            w.value(uint64_t(done.rays));
            w.u32(uint32_t(batch.size()));
            for (const uint32_t t : batch) {
                w.u32(t);
                write_tile_pixels(w, film, aovs, grid.bounds(t));
            }
            MPI_Send(w.bytes().data(), int(w.bytes().size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD);
            stats.rays += done.rays;
        }
        return stats;
    }

    // Rank 0: a thread of its own renders from the queue while this one answers the others.
    const std::vector<uint32_t> order = grid.tiles_overlapping(settings.crop);
    const auto total = uint32_t(order.size());
    TileQueue queue(order, size_);
    std::atomic<uint32_t> finished{0};
    std::atomic<uint64_t> rays{0};
    std::exception_ptr local_failure;
    std::thread local([&] {
        try {
            for (std::vector<uint32_t> batch = queue.take(); !batch.empty(); batch = queue.take()) {
                rays += integrator.render_tiles(scene, settings, film, batch, aovs).rays;
                finished += uint32_t(batch.size());
            }
        } catch (...) {
            local_failure = std::current_exception();
        }
    });
    uint32_t shown = 0;
    const auto show_progress = [&] {
        if (const uint32_t now = finished.load(); progress && now != shown) progress(shown = now, total);
    };
    for (int done_ranks = 0; done_ranks < size_ - 1;) {
        const MPI_Status status = wait_for_message(MPI_ANY_SOURCE, MPI_ANY_TAG, *this, stop, show_progress);
        const std::string bytes = receive_bytes(status);
        if (status.MPI_TAG == kResult) {
            try {
                ByteReader r(bytes);
                rays += r.value<uint64_t>();
                const uint32_t count = r.u32();
                for (uint32_t i = 0; i < count; ++i) {
                    const uint32_t t = r.u32();
                    if (t >= grid.count()) throw ByteStreamError("a tile out of the grid");
                    read_tile_pixels(r, film, aovs, grid.bounds(t));
                }
                finished += count;
            } catch (const ByteStreamError&) {
                abort(fmt::format("rank {} sent tiles that are not this render's", status.MPI_SOURCE));
            }
        }
        const std::vector<uint32_t> batch = queue.take();
        MPI_Send(batch.data(), int(batch.size()), MPI_UINT32_T, status.MPI_SOURCE, kWork, MPI_COMM_WORLD);
        if (batch.empty()) ++done_ranks;
    }
    local.join();
    if (local_failure) {
        try {
            std::rethrow_exception(local_failure);
        } catch (const std::exception& e) {
            abort(e.what());
        }
    }
    show_progress();
    stats.rays = rays.load();
    stats.tiles = stats.tiles_done = total;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace glint::app
