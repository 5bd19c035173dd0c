// The Sampler: stratified in every dimension over a pixel's samples, deterministic per
// (seed, pixel, sample index), and compatible with the first tracer's pixel jitter.

#include "glint/sampling/sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

using namespace glint;

TEST(Sampler, PixelDimensionReproducesTheOriginalJitter) {
    // Glint's first tracer drew (jx, jy) per sample, in order, from PCG32(seed, pixel),
    // 24 bits per float: the reference images depend on exactly these positions.
    constexpr uint32_t n = 3;
    pcg32 rng(42, 1234);
    auto uniform = [&] { return float(rng() >> 8) * 0x1p-24f; };
    Sampler sampler(42, n);
    for (uint32_t index = 0; index < n * n; ++index) {
        const float jx = (float(index % n) + uniform()) / float(n);
        const float jy = (float(index / n) + uniform()) / float(n);
        sampler.start_pixel_sample(1234, index);
        EXPECT_EQ(sampler.pixel_2d().x, jx);
        EXPECT_EQ(sampler.pixel_2d().y, jy);
    }
}

TEST(Sampler, EveryDimensionIsStratifiedOverThePixelsSamples) {
    constexpr uint32_t n = 4;
    Sampler sampler(7, n);
    constexpr int kDimensions = 12;
    std::vector<std::set<uint32_t>> strata_1d(kDimensions), cells_2d(kDimensions);
    for (uint32_t index = 0; index < n * n; ++index) {
        sampler.start_pixel_sample(99, index);
        for (int d = 0; d < kDimensions; ++d) {
            const float x = sampler.next_1d();
            ASSERT_GE(x, 0.0f);
            ASSERT_LT(x, 1.0f);
            strata_1d[d].insert(uint32_t(x * float(n * n)));
            const Vec2 u = sampler.next_2d();
            cells_2d[d].insert(uint32_t(u.x * float(n)) + n * uint32_t(u.y * float(n)));
        }
    }
    for (int d = 0; d < kDimensions; ++d) {
        EXPECT_EQ(strata_1d[d].size(), n * n) << "1-D dimension " << d << " repeats a stratum";
        EXPECT_EQ(cells_2d[d].size(), n * n) << "2-D dimension " << d << " repeats a cell";
    }
}

TEST(Sampler, SameInputsSameNumbersOtherPixelsOtherNumbers) {
    Sampler a(5, 2), b(5, 2);
    a.start_pixel_sample(10, 3);
    b.start_pixel_sample(10, 3);
    EXPECT_EQ(a.next_1d(), b.next_1d());
    EXPECT_EQ(a.next_2d(), b.next_2d());
    Sampler c(5, 2);
    c.start_pixel_sample(11, 3);
    a.start_pixel_sample(10, 3);
    EXPECT_NE(a.next_1d(), c.next_1d());
}

TEST(Sampler, SampleSetsAreStratifiedInBothProjections) {
    // Kensler's correlated multi-jitter on an m×n grid (m = ⌊√N⌋, n = ⌈N/m⌉): y falls in
    // N distinct strata of height 1/N, x in distinct strata of width 1/(m·n). Grids of up
    // to 64 × 64 take their column and row permutations from tables, larger ones (65 × 65,
    // 64 × 65) one by one.
    for (const uint32_t count : {1u, 5u, 16u, 24u, 30u, 100u, 4225u, 4160u}) {
        Sampler sampler(3, 1);
        sampler.start_pixel_sample(0, 0);
        std::vector<Vec2> points(count);
        sampler.next_2d_set(points);
        const auto m = uint32_t(std::sqrt(double(count)));
        const uint32_t cells = m * ((count + m - 1) / m);
        std::set<uint32_t> columns, rows;
        for (const Vec2& p : points) {
            ASSERT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f);
            columns.insert(uint32_t(p.x * float(cells)));
            rows.insert(uint32_t(p.y * float(count)));
        }
        EXPECT_EQ(columns.size(), count);
        EXPECT_EQ(rows.size(), count);
    }
}

TEST(Sampler, PermutationElementIsAPermutation) {
    for (const uint32_t l : {1u, 7u, 64u, 100u}) {
        std::set<uint32_t> seen;
        for (uint32_t i = 0; i < l; ++i) seen.insert(permutation_element(i, l, 0xdeadbeefu));
        EXPECT_EQ(seen.size(), l);
        EXPECT_LT(*seen.rbegin(), l);
    }
}
