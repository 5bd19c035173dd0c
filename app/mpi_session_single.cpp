// MpiSession without MPI (Glint built without Open MPI): every run is one process.

#include "mpi_session.h"

#include <fmt/core.h>

#include <cstdlib>

namespace glint::app {

MpiSession::MpiSession(int& /*argc*/, char**& /*argv*/) {}

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
