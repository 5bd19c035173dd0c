#include "progress_bar.h"

#include "glint/util/progress_text.h"

#include <fmt/core.h>

#include <cstdio>

namespace glint::app {

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressBar::update(uint32_t done, uint32_t total) {
    if (!enabled_ || total == 0) return;
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (done != total && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    fmt::print(stderr, "\r{} ", progress_text(double(done) / double(total), elapsed));
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!enabled_) return;
    fmt::print(stderr, "\r{:80}\r", "");
    std::fflush(stderr);
}

}  // namespace glint::app
