// MpiSession of `glint`, which never loads Open MPI: every run is one process. Started by an
// MPI launcher, it hands the process to `glint-mpi` (when Glint was built with Open MPI), the
// same command line with mpi_session.cpp.

#include "mpi_session.h"

#include "mpi_launcher.h"
#include "program_beside.h"

#include <fmt/core.h>

#include <cstdlib>

namespace glint::app {

MpiSession::MpiSession(int& argc, char**& argv) {
#ifdef GLINT_MPI_PROGRAM
    if (launched_by_mpi()) abort(run_program_beside(GLINT_MPI_PROGRAM, argc, argv) + " (it is built with glint)");
#else
    (void)argc;
    (void)argv;
#endif
}

MpiSession::~MpiSession() = default;

void MpiSession::abort(const std::string& message) const {
    fmt::print(stderr, "glint: error: {}\n", message);
    std::exit(1);
}

void MpiSession::check_same_render(const RenderFingerprint& /*fingerprint*/) const {}

RenderStats MpiSession::render(const Integrator& integrator, const RenderScene& scene, const RenderSettings& settings,
                               Film& film, AovFilm* aovs, const Integrator::ProgressCallback& progress,
                               const std::atomic<bool>& stop) const {
    return integrator.render(scene, settings, film, progress, &stop, nullptr, aovs);
}

}  // namespace glint::app
