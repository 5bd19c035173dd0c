#pragma once
/// \file Per-pixel random numbers that do not depend on the thread schedule.

#include <cstdint>
#include <pcg_random.hpp>

namespace glint {

/// PCG32 (O'Neill 2014) seeded from (render seed, pixel index): every pixel owns an
/// independent stream, so an image is bit-identical for any thread count or tile order.
class Rng {
public:
    Rng(uint64_t seed, uint64_t stream) : engine_(seed, stream) {}

    /// Uniform float in [0, 1).
    [[nodiscard]] float uniform() {
        // 24 random mantissa bits: exact floats, never 1.0f.
        return static_cast<float>(engine_() >> 8) * 0x1p-24f;
    }

private:
    pcg32 engine_;
};

}  // namespace glint
