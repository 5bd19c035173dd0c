#include "glint/sampling/sampler.h"

#include <cmath>
#include <pcg_random.hpp>

namespace glint {

namespace {

/// Murmur3's 64-bit finaliser: a bijective mix, so distinct inputs give distinct hashes.
constexpr uint64_t mix64(uint64_t v) {
    v ^= v >> 33;
    v *= 0xff51afd7ed558ccdull;
    v ^= v >> 33;
    v *= 0xc4ceb9fe1a85ec53ull;
    v ^= v >> 33;
    return v;
}

/// A float in [0, 1) from the top 24 bits of a hash: exact, never 1.
constexpr float unit_float(uint64_t bits) { return float(bits >> 40) * 0x1p-24f; }

}  // namespace

uint32_t permutation_element(uint32_t i, uint32_t l, uint32_t p) {
    // Kensler 2013, Listing 3: a hash on the smallest power of two ≥ l, with cycle walking.
    uint32_t w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= p;
        i *= 0xe170893du;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3fu;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | p >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= l);
    return (i + p) % l;
}

namespace {

/// Kensler 2013, Listing 4: a float in [0, 1) hashed from (i, p).
float hashed_float(uint32_t i, uint32_t p) {
    i ^= p;
    i ^= i >> 17;
    i ^= i >> 10;
    i *= 0xb36534e5u;
    i ^= i >> 12;
    i ^= i >> 21;
    i *= 0x93fc4795u;
    i ^= 0xdf6e307fu;
    i ^= i >> 17;
    i *= 1u | p >> 18;
    return float(i >> 8) * 0x1p-24f;
}

}  // namespace

Vec2 correlated_multi_jitter(uint32_t s, uint32_t count, uint32_t p) {
    const auto m = static_cast<uint32_t>(std::sqrt(double(count)));
    const uint32_t n = (count + m - 1) / m;
    s = permutation_element(s, count, p * 0x51633e2du);
    const uint32_t sx = permutation_element(s % m, m, p * 0x68bc21ebu);
    const uint32_t sy = permutation_element(s / m, n, p * 0x02e5be93u);
    const float jx = hashed_float(s, p * 0x967a889bu);
    const float jy = hashed_float(s, p * 0x368cc8b7u);
    const float x = (float(sx) + (float(sy) + jx) / float(n)) / float(m);
    const float y = (float(s) + jy) / float(count);
    // Rounding can land exactly on 1 for the last stratum; keep the half-open interval.
    return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
}

Sampler::Sampler(uint64_t seed, uint32_t samples_per_axis) : seed_(seed), n_(samples_per_axis < 1 ? 1 : samples_per_axis) {}

uint64_t Sampler::dimension_hash(uint32_t dimension) const {
    return mix64(mix64(mix64(seed_ ^ 0x9e3779b97f4a7c15ull) ^ pixel_) ^ dimension);
}

float Sampler::next_1d() {
    const uint64_t h = dimension_hash(dimension_++);
    const uint32_t strata = n_ * n_;
    const uint32_t stratum = permutation_element(index_, strata, uint32_t(h));
    const float jitter = unit_float(mix64(h ^ index_));
    return std::min((float(stratum) + jitter) / float(strata), 0x1.fffffep-1f);
}

Vec2 Sampler::next_2d() {
    const uint64_t h = dimension_hash(dimension_++);
    const uint32_t stratum = permutation_element(index_, n_ * n_, uint32_t(h));
    const uint64_t j = mix64(h ^ index_);
    const float x = (float(stratum % n_) + unit_float(j)) / float(n_);
    const float y = (float(stratum / n_) + unit_float(j << 24)) / float(n_);
    return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
}

void Sampler::next_2d_set(std::span<Vec2> out) {
    const uint64_t h = dimension_hash(dimension_++);
    // A fresh pattern for every pixel sample, so the sets of different samples differ.
    const auto pattern = uint32_t(mix64(h ^ index_));
    for (uint32_t s = 0; s < out.size(); ++s) out[s] = correlated_multi_jitter(s, uint32_t(out.size()), pattern);
}

}  // namespace glint
