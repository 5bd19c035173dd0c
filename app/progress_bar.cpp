#include "progress_bar.h"

#include <fmt/core.h>

#include <cstdio>
#include <string>

namespace glint::app {

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressBar::update(uint32_t done, uint32_t total) {
    if (!enabled_ || total == 0) return;
    std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (done != total && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    const double fraction = double(done) / double(total);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    constexpr int kWidth = 40;
    const int filled = static_cast<int>(fraction * kWidth);
    const std::string bar = std::string(size_t(filled), '#') + std::string(size_t(kWidth - filled), '.');
    fmt::print(stderr, "\r[{}] {:5.1f}%  elapsed {:.1f} s  ETA {:.1f} s ", bar, 100.0 * fraction, elapsed, eta);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!enabled_) return;
    fmt::print(stderr, "\r{:80}\r", "");
    std::fflush(stderr);
}

}  // namespace glint::app
