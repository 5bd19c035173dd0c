#pragma once
/// \file What the Whitted integrator's shading (whitted_integrator.cpp) and its direct light
/// (whitted_direct_light.cpp) both draw on: stratified sets of sample points and the MIS
/// weight of a glossy sample against a light sample. Internal to those two files.

#include "glint/math/vec2.h"
#include "glint/sampling/sampler.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace glint::whitted {

/// `count` points of the sampler's next dimension, stratified among themselves; in `small`
/// when they fit, so that the usual counts allocate nothing.
inline std::span<Vec2> stratified_set(Sampler& sampler, uint32_t count, std::array<Vec2, 16>& small,
                                      std::vector<Vec2>& large) {
    std::span<Vec2> us(small.data(), count);
    if (count > small.size()) {
        large.resize(count);
        us = large;
    }
    sampler.next_2d_set(us);
    return us;
}

/// Veach's power heuristic (β = 2) for a strategy against another, each given as its sample
/// count times its density (Veach 1997, eq. 9.13); written as a ratio so that an infinite
/// or huge density (a near-delta lobe, a distant small light) cannot overflow.
inline float power_heuristic(float n_pdf, float other_n_pdf) {
    if (!(n_pdf > 0.0f)) return 0.0f;
    const float r = other_n_pdf / n_pdf;
    return 1.0f / (1.0f + r * r);
}

}  // namespace glint::whitted
