#include "glint/sampling/sampler.h"

#include <algorithm>
#include <array>
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

namespace {

/// permutation_element, inlined where a set takes many elements.
[[gnu::always_inline]] inline uint32_t permute(uint32_t i, uint32_t l, uint32_t p) {
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
    // (i + p) mod l: a mask where l is a power of two, not a division.
    return (l & (l - 1)) == 0 ? (i + p) & (l - 1) : (i + p) % l;
}

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

/// Correlated multi-jittered points (Kensler 2013, Listing 6) of one set: `count` points in
/// an m×n grid, the samples, the grid's columns and its rows each shuffled by their own
/// permutation of `pattern`.
struct MultiJitterGrid {
    /// The set's size and the grid's sides, each a divisor of every point (for the usual
    /// sets of 4, 16 or 64 points, powers of two: shifts and products).
    Divisor count, m, n;
    uint32_t pattern;
    MultiJitterGrid(uint32_t count_, uint32_t pattern_)
        : count(count_), m(side(count_)), n((count_ + m.value() - 1) / m.value()), pattern(pattern_) {}
    /// m = ⌊√count⌋.
    static uint32_t side(uint32_t count) { return static_cast<uint32_t>(std::sqrt(double(count))); }
    /// Where sample s goes: its shuffled index, whose column is its index mod m and whose
    /// row its index / m.
    [[nodiscard]] uint32_t shuffled(uint32_t s) const { return permute(s, count.value(), pattern * 0x51633e2du); }
    /// Where column c and row r go.
    [[nodiscard]] uint32_t column(uint32_t c) const { return permute(c, m.value(), pattern * 0x68bc21ebu); }
    [[nodiscard]] uint32_t row(uint32_t r) const { return permute(r, n.value(), pattern * 0x02e5be93u); }
    /// The point of shuffled sample s in column sx and row sy.
    [[nodiscard]] Vec2 point(uint32_t s, uint32_t sx, uint32_t sy) const {
        const float jx = hashed_float(s, pattern * 0x967a889bu);
        const float jy = hashed_float(s, pattern * 0x368cc8b7u);
        const float x = m.divide(float(sx) + n.divide(float(sy) + jx));
        const float y = count.divide(float(s) + jy);
        // Rounding can land exactly on 1 for the last stratum; keep the half-open interval.
        return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
    }
    /// Sample s, its column and row permuted on the spot.
    [[nodiscard]] Vec2 sample(uint32_t s) const {
        const uint32_t i = shuffled(s);
        return point(i, column(m.remainder(i)), row(m.quotient(i)));
    }
};

}  // namespace

uint32_t permutation_element(uint32_t i, uint32_t l, uint32_t p) { return permute(i, l, p); }

Vec2 correlated_multi_jitter(uint32_t s, uint32_t count, uint32_t p) { return MultiJitterGrid(count, p).sample(s); }

Sampler::Sampler(uint64_t seed, uint32_t samples_per_axis)
    : seed_(seed),
      seed_hash_(mix64(seed ^ 0x9e3779b97f4a7c15ull)),
      by_n_(samples_per_axis < 1 ? 1 : samples_per_axis),
      by_strata_(by_n_.value() * by_n_.value()),
      pixel_hash_(hash_pixel(0)) {}

uint64_t Sampler::hash_pixel(uint64_t pixel) const { return mix64(seed_hash_ ^ pixel); }

uint64_t Sampler::dimension_hash(uint32_t dimension) const { return mix64(pixel_hash_ ^ dimension); }

float Sampler::next_1d() {
    const uint64_t h = dimension_hash(dimension_++);
    const uint32_t stratum = permute(index_, by_strata_.value(), uint32_t(h));
    const float jitter = unit_float(mix64(h ^ index_));
    return std::min(by_strata_.divide(float(stratum) + jitter), 0x1.fffffep-1f);
}

Vec2 Sampler::next_2d() {
    const uint64_t h = dimension_hash(dimension_++);
    const uint32_t stratum = permute(index_, by_strata_.value(), uint32_t(h));
    const uint64_t j = mix64(h ^ index_);
    const float x = by_n_.divide(float(by_n_.remainder(stratum)) + unit_float(j));
    const float y = by_n_.divide(float(by_n_.quotient(stratum)) + unit_float(j << 24));
    return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
}

void Sampler::next_2d_set(std::span<Vec2> out) {
    const uint64_t h = dimension_hash(dimension_++);
    // A fresh pattern for every pixel sample, so the sets of different samples differ.
    const auto pattern = uint32_t(mix64(h ^ index_));
    const MultiJitterGrid grid(uint32_t(out.size()), pattern);
    // correlated_multi_jitter for each sample, with the permutations of the grid's m columns
    // and n rows taken once for the set, not once per sample (for grids of up to 64 × 64).
    constexpr uint32_t kMaxSide = 64;
    if (grid.m.value() > kMaxSide || grid.n.value() > kMaxSide) {
        for (uint32_t s = 0; s < out.size(); ++s) out[s] = grid.sample(s);
        return;
    }
    std::array<uint32_t, kMaxSide> columns, rows;
    for (uint32_t c = 0; c < grid.m.value(); ++c) columns[c] = grid.column(c);
    for (uint32_t r = 0; r < grid.n.value(); ++r) rows[r] = grid.row(r);
    for (uint32_t s = 0; s < out.size(); ++s) {
        const uint32_t shuffled = grid.shuffled(s);
        out[s] = grid.point(shuffled, columns[grid.m.remainder(shuffled)], rows[grid.m.quotient(shuffled)]);
    }
}

}  // namespace glint
