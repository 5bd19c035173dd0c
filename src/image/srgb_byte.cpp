#include "glint/image/srgb_byte.h"

#include "glint/math/color.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace glint {

namespace {

/// thresholds[b - 1]: the least linear value whose level is b or more (b = 1..255).
std::array<float, 255> srgb_thresholds() {
    std::array<float, 255> thresholds{};
    for (int level = 1; level <= 255; ++level) {
        // The level of a positive float rises with its bit pattern: bisect the patterns in
        // (0, 1] for the first one at `level` or above.
        uint32_t below = 0, at_or_above = std::bit_cast<uint32_t>(1.0f);
        while (at_or_above - below > 1) {
            const uint32_t middle = below + (at_or_above - below) / 2;
            if (display_byte(linear_to_srgb(std::bit_cast<float>(middle))) >= level)
                at_or_above = middle;
            else
                below = middle;
        }
        thresholds[std::size_t(level - 1)] = std::bit_cast<float>(at_or_above);
    }
    return thresholds;
}

}  // namespace

uint8_t display_byte(float display) {
    return uint8_t(display > 0.0f ? std::lround(std::min(display, 1.0f) * 255.0f) : 0);
}

uint8_t srgb_byte(float linear) {
    static const std::array<float, 255> thresholds = srgb_thresholds();
    // The levels `linear` reaches (NaN reaches none), by steps of 128, 64, ..., 1: at most 255.
    std::size_t level = 0;
    for (std::size_t step = 128; step > 0; step /= 2)
        if (thresholds[level + step - 1] <= linear) level += step;
    return uint8_t(level);
}

}  // namespace glint
