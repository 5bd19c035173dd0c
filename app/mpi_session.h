#pragma once
// One image across many processes: `mpirun -np N glint render SCENE -o OUT` (or srun under
// Slurm). Every rank loads the scene; rank 0 hands out tiles from a work queue, as few at a
// time as keep the ranks busy (tiles differ in cost by orders of magnitude, so a fixed split
// would leave ranks idle: OSPRay's MPI load balancer deals dynamically too), renders tiles
// itself between requests, collects the others' accumulators (integrators/tile_pixels.h)
// and writes the image, bit for bit the one a single process renders. A rank that fails
// ends the whole job with its message (MPI_Abort) rather than leaving the others waiting.
//
// Built with Open MPI when CMake finds it (mpi_session.cpp); without it every run is one
// process (mpi_session_single.cpp).

#include "glint/image/aov_film.h"
#include "glint/image/film.h"
#include "glint/integrators/checkpoint.h"
#include "glint/integrators/integrator.h"

#include <atomic>
#include <string>

namespace glint::app {

class MpiSession {
public:
    /// Starts MPI when the process was launched by an MPI launcher (its environment says so)
    /// and Glint was built with MPI; otherwise a session of this one process.
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    [[nodiscard]] int rank() const { return rank_; }
    [[nodiscard]] int size() const { return size_; }
    [[nodiscard]] bool distributed() const { return size_ > 1; }

    /// End every rank: `message` on this rank's stderr, exit status 1 for the job.
    [[noreturn]] void abort(const std::string& message) const;

    /// Every rank must render the same image: rank 0 sends its fingerprint, and a rank
    /// whose own differs (another scene file on its node, say) ends the job saying what.
    void check_same_render(const RenderFingerprint& fingerprint) const;

    /// Render the tiles of `film` (those the crop overlaps) across the ranks; on rank 0,
    /// `film` and `aovs` then hold every tile. `progress` is called on rank 0 as tiles
    /// arrive. A `stop` request (SIGINT, SIGTERM) ends the job. Returns the rays of all ranks.
    RenderStats render(const Integrator& integrator, const RenderScene& scene, const RenderSettings& settings,
                       Film& film, AovFilm* aovs, const Integrator::ProgressCallback& progress,
                       const std::atomic<bool>& stop) const;

private:
    int rank_ = 0, size_ = 1;
    bool started_ = false;
};

}  // namespace glint::app
