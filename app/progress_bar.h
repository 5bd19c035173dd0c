#pragma once
/// \file A terminal progress bar with an ETA, drawn on stderr.

#include <chrono>
#include <cstdint>
#include <mutex>

namespace glint::app {

class ProgressBar {
public:
    /// Draws only when `enabled` (stderr is a terminal and --quiet was not given).
    explicit ProgressBar(bool enabled);
    /// Thread-safe; redraws at most ten times a second.
    void update(uint32_t done, uint32_t total);
    /// Clears the bar's line.
    void finish();

private:
    bool enabled_;
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace glint::app
