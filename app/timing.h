#pragma once
// Wall-clock times of a command's phases (load, build), as `render` and `info` report them.

#include <chrono>

namespace glint::app {

using Clock = std::chrono::steady_clock;

/// Seconds elapsed since `start`.
inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace glint::app
