#include "glint/image/srgb_byte.h"

#include "glint/math/color.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace glint {

namespace {

/// Floats in [0, 1) by their top 16 bits (sign, exponent, 7 bits of mantissa): 16,256
/// buckets, each narrower than the steps between levels where it lies, so at most one
/// threshold falls inside a bucket. A bucket is 2⁻⁷ to 2⁻⁸ of its values and a step of the
/// power segment 0.0089·x^0.583 wide, so the widest against its steps is just below 1:
/// 0.0039 against 0.0089 (SrgbByte.* fail with buckets eight times wider).
constexpr int kBucketShift = 16;
constexpr std::size_t kBuckets = std::bit_cast<uint32_t>(1.0f) >> kBucketShift;

struct SrgbLevels {
    /// thresholds[b - 1]: the least linear value whose level is b or more (b = 1..255).
    std::array<float, 255> thresholds{};
    /// The level of the least float of each bucket.
    std::array<uint8_t, kBuckets> bucket_levels{};

    /// The number of thresholds `linear` has reached, by halving (at most 8 comparisons).
    uint8_t count_reached(float linear) const {
        std::size_t level = 0;
        for (std::size_t step = 128; step > 0; step /= 2)
            if (thresholds[level + step - 1] <= linear) level += step;
        return uint8_t(level);
    }
};

SrgbLevels find_levels() {
    SrgbLevels levels;
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
        levels.thresholds[std::size_t(level - 1)] = std::bit_cast<float>(at_or_above);
    }
    for (std::size_t bucket = 0; bucket < kBuckets; ++bucket)
        levels.bucket_levels[bucket] = levels.count_reached(std::bit_cast<float>(uint32_t(bucket << kBucketShift)));
    return levels;
}

}  // namespace

uint8_t display_byte(float display) {
    return uint8_t(display > 0.0f ? std::lround(std::min(display, 1.0f) * 255.0f) : 0);
}

uint8_t srgb_byte(float linear) {
    static const SrgbLevels levels = find_levels();
    if (!(linear > 0.0f)) return 0;  // NaN too
    if (linear >= 1.0f) return 255;
    // The bucket's first level, and the one step up that may lie inside the bucket.
    const uint8_t level = levels.bucket_levels[std::bit_cast<uint32_t>(linear) >> kBucketShift];
    return uint8_t(level + (level < 255 && levels.thresholds[level] <= linear));
}

}  // namespace glint
