#pragma once
// --threads for a whole command: `render` and `view` bound every oneTBB pool of the process
// (loading, the build, the render, the image's encoding) to it, not only the render's tiles.

#include <tbb/global_control.h>

#include <cstdint>
#include <optional>

namespace glint::app {

/// Bounds every oneTBB pool of the process to `threads` while it lives; 0 leaves every core.
/// A user who asks for N threads on a shared machine means the whole process.
/// max_render_threads() counts the bound.
class ThreadLimit {
public:
    explicit ThreadLimit(uint32_t threads) {
        if (threads > 0) control_.emplace(tbb::global_control::max_allowed_parallelism, threads);
    }

private:
    std::optional<tbb::global_control> control_;
};

}  // namespace glint::app
