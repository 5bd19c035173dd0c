#include "glint/image/display_transform.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace glint {

float auto_exposure_stops(const Image& image) {
    // Luminances below this are black for the meter: 2^-40 of white, far under any
    // displayable value, yet far above denormals.
    constexpr double kBlack = 1e-12;
    if (image.channels < 3) return 0.0f;
    double log_sum = 0.0;
    std::size_t lit = 0;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        const float* v = &image.pixels[p * std::size_t(image.channels)];
        const double luminance = Color(v[0], v[1], v[2]).luminance();
        if (!(luminance > kBlack) || !std::isfinite(luminance)) continue;
        log_sum += std::log(luminance);
        ++lit;
    }
    if (lit == 0) return 0.0f;
    const double log_average = std::exp(log_sum / double(lit));
    return float(std::log2(double(kMiddleGrey) / log_average));
}

std::optional<Exposure> parse_exposure(std::string_view text) {
    if (text == "auto") return Exposure{true, 0.0f};
    const std::string s(text);
    char* end = nullptr;
    const float stops = std::strtof(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(stops)) return std::nullopt;
    return Exposure{false, stops};
}

}  // namespace glint
