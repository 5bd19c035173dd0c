#pragma once
// Ctrl-C and SIGTERM during a render: the first asks the render to stop after the tiles in
// flight, so that what is rendered can be written; the second ends the process at once,
// after removing the image being written, if any (its final name is only ever a complete
// image: write_image renames a finished temporary file into place).

#include <atomic>
#include <filesystem>

namespace glint::app {

/// Catches SIGINT and SIGTERM while it lives; restores the previous handlers after.
/// One at a time: POSIX handlers are process-wide, so the state they set is too.
class InterruptGuard {
public:
    /// `output` is the image the render will write (its temporary name is removed on a
    /// second signal).
    explicit InterruptGuard(const std::filesystem::path& output);
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// Set by the first signal; hand it to Integrator::render.
    [[nodiscard]] const std::atomic<bool>& stop() const;
    /// The signal that arrived (SIGINT or SIGTERM), 0 if none.
    [[nodiscard]] int signal() const;
};

}  // namespace glint::app
