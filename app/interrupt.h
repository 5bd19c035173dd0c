#pragma once
// Ctrl-C and SIGTERM during a render: the first asks the render to stop after the tiles in
// flight, so that what is rendered can be written; the second ends the process at once,
// after removing the files being written, if any (final names only ever hold complete
// files: images and checkpoints are renamed into place when finished).

#include <atomic>
#include <filesystem>

namespace glint::app {

/// Catches SIGINT and SIGTERM while it lives; restores the previous handlers after.
/// One at a time: POSIX handlers are process-wide, so the state they set is too.
class InterruptGuard {
public:
    /// `temporaries`: the temporary names of the files the render may be writing (the image
    /// and its checkpoint), removed on a second signal.
    InterruptGuard(const std::filesystem::path& image_temporary, const std::filesystem::path& checkpoint_temporary);
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// Set by the first signal; hand it to Integrator::render.
    [[nodiscard]] const std::atomic<bool>& stop() const;
    /// The signal that arrived (SIGINT or SIGTERM), 0 if none.
    [[nodiscard]] int signal() const;
};

}  // namespace glint::app
