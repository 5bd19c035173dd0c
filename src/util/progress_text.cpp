#include "glint/util/progress_text.h"

#include <fmt/core.h>

#include <algorithm>

namespace glint {

std::string progress_text(double fraction, double elapsed_seconds) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const double eta = fraction > 0.0 ? elapsed_seconds * (1.0 - fraction) / fraction : 0.0;
    constexpr int kWidth = 40;
    const auto filled = std::size_t(fraction * kWidth);
    return fmt::format("[{}{}] {:5.1f}%  elapsed {:.1f} s  ETA {:.1f} s", std::string(filled, '#'),
                       std::string(kWidth - filled, '.'), 100.0 * fraction, elapsed_seconds, eta);
}

}  // namespace glint
