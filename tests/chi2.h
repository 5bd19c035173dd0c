#pragma once
/// \file Pearson's chi-square goodness-of-fit test for sampling routines, in the manner of
/// Mitsuba 3's `chi2.py` and nori's `chi2test`: draw many samples, histogram them on a grid,
/// integrate the claimed pdf over every cell, and ask how likely the histogram is if the
/// sampler really has that pdf. Header-only; used by tests/sampling_test.cpp.

#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <pcg_random.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace glint {

/// Outcome of a chi-square test; `report` gives the statistic, dof and p-value, and on
/// failure the reason and the cells that deviate most.
struct Chi2Result {
    bool passed;
    double p_value;
    std::string report;
};

/// Regularised upper incomplete gamma function Q(a, x) = Γ(a, x)/Γ(a), for a > 0, x ≥ 0:
/// the probability that a χ² variable with 2a degrees of freedom exceeds 2x. Numerical
/// Recipes (Press et al., 3rd ed., §6.2) `gammq`: the series for P = 1 − Q below x = a + 1,
/// where it converges fast, and Lentz's continued fraction for Q above, where the series
/// would need O(x) terms and 1 − P would cancel.
inline double regularized_upper_gamma(double a, double x) {
    if (x <= 0.0) return 1.0;
    constexpr double kEps = 1e-15;
    constexpr double kTiny = 1e-300;
    const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);  // log(x^a e^-x / Γ(a))
    if (x < a + 1.0) {
        // P(a, x) = x^a e^-x / Γ(a) · Σ x^n / (a (a+1) … (a+n)).
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000 && std::abs(term) > std::abs(sum) * kEps; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::max(0.0, 1.0 - sum * std::exp(log_prefactor));
    }
    // Q(a, x) = x^a e^-x / Γ(a) · 1/(x+1−a− 1·(1−a)/(x+3−a− 2·(2−a)/(x+5−a− …))), modified Lentz.
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kEps) break;
    }
    return std::exp(log_prefactor) * h;
}

/// Pearson's test of observed cell counts against expected ones (sample_count × the cell's
/// probability). The cells need not cover every outcome: what the observed and expected
/// totals fall short of `sample_count` forms one more cell (rejected samples, samples off the
/// grid). Cells expecting fewer than 5 samples are pooled, smallest first, into groups
/// expecting at least 5 (as Mitsuba's chi2.py), since the χ² approximation needs them;
/// dof = cells after pooling − 1. Any sample in a cell expecting ≈0 fails outright. The p-value
/// is Q(dof/2, χ²/2); it is compared against the Šidák-corrected 1 − (1 − α)^(1/test_count), so
/// that `test_count` tests together reject a correct sampler with probability α.
inline Chi2Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected,
                            std::size_t sample_count, double significance = 0.01, int test_count = 1) {
    std::ostringstream out;
    if (observed.size() != expected.size()) {
        out << "observed has " << observed.size() << " cells, expected " << expected.size();
        return {false, 0.0, out.str()};
    }
    const double n = static_cast<double>(sample_count);
    double observed_sum = 0.0, expected_sum = 0.0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        observed_sum += observed[i];
        expected_sum += expected[i];
    }
    struct Cell {
        std::size_t index;
        double observed, expected;
    };
    std::vector<Cell> cells;
    for (std::size_t i = 0; i < observed.size(); ++i) cells.push_back({i, observed[i], expected[i]});
    cells.push_back({observed.size(), n - observed_sum, std::max(0.0, n - expected_sum)});
    out << "samples " << sample_count << ", observed in cells " << observed_sum << ", expected in cells "
        << expected_sum << " (cell " << observed.size() << " is the remainder)\n";

    // A cell this unlikely to receive even one sample counts as impossible.
    constexpr double kZeroExpected = 1e-6;
    bool impossible = false;
    for (const Cell& c : cells) {
        if (c.expected < kZeroExpected && c.observed != 0.0) {
            if (!impossible) out << "FAIL: samples in cells whose expected count is ~0:";
            out << " cell " << c.index << " got " << c.observed << " (expected " << c.expected << ");";
            impossible = true;
        }
    }
    if (impossible) out << '\n';
    if (observed_sum > n) {
        out << "FAIL: more samples in the cells than were drawn\n";
        impossible = true;
    }

    std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.expected < b.expected; });
    double chi2 = 0.0, pool_observed = 0.0, pool_expected = 0.0;
    int groups = 0, pooled = 0;
    double last_observed = 0.0, last_expected = 0.0;  // the last group, which takes a leftover pool
    for (const Cell& c : cells) {
        if (c.expected < kZeroExpected) continue;
        const bool pooling = c.expected < 5.0 || pool_expected > 0.0;
        if (pooling) ++pooled;
        pool_observed += c.observed;
        pool_expected += c.expected;
        if (pool_expected >= 5.0) {
            const double d = pool_observed - pool_expected;
            chi2 += d * d / pool_expected;
            last_observed = pool_observed;
            last_expected = pool_expected;
            pool_observed = pool_expected = 0.0;
            ++groups;
        }
    }
    if (pool_expected > 0.0 && groups > 0) {
        // Leftover small cells join the last (largest) group rather than being dropped.
        double d = last_observed - last_expected;
        chi2 -= d * d / last_expected;
        d = last_observed + pool_observed - last_expected - pool_expected;
        chi2 += d * d / (last_expected + pool_expected);
    }
    const int dof = groups - 1;
    const double p_value = dof >= 1 ? regularized_upper_gamma(0.5 * dof, 0.5 * chi2) : 0.0;
    const double alpha = 1.0 - std::pow(1.0 - significance, 1.0 / test_count);
    const bool passed = !impossible && dof >= 1 && std::isfinite(p_value) && p_value >= alpha;
    out << "chi2 = " << chi2 << ", dof = " << dof << ", p-value = " << p_value << " (significance " << alpha
        << " after Sidak correction for " << test_count << " tests); " << pooled << " cells pooled\n";
    if (dof < 1) out << "FAIL: fewer than two cells with enough expected samples\n";
    if (!passed) {
        // The cells that deviate most, in standard deviations, to show where the fit breaks.
        std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) {
            auto z = [](const Cell& c) { return std::abs(c.observed - c.expected) / std::sqrt(c.expected + 1.0); };
            return z(a) > z(b);
        });
        out << "largest deviations:";
        for (std::size_t i = 0; i < std::min<std::size_t>(6, cells.size()); ++i) {
            out << " cell " << cells[i].index << " observed " << cells[i].observed << " expected " << cells[i].expected
                << ";";
        }
        out << '\n';
    }
    return {passed, p_value, out.str()};
}

namespace chi2_detail {

/// One step of adaptive Simpson on [a, b], given f at a, the midpoint and b and the
/// one-panel estimate `whole`: split in two, and recurse where the halves disagree with it.
template <class F>
double simpson_refine(const F& f, double a, double b, double fa, double fm, double fb, double whole, double eps,
                      int depth) {
    const double m = 0.5 * (a + b);
    const double flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double delta = left + right - whole;
    // |delta|/15 estimates the error of left + right (Lyness 1969), and adding it back is
    // Richardson extrapolation.
    if (depth <= 0 || std::abs(delta) <= 15.0 * eps) return left + right + delta / 15.0;
    return simpson_refine(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           simpson_refine(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

/// ∫ f over [a, b] by adaptive Simpson to absolute error ~eps, at most 2^depth intervals.
template <class F>
double adaptive_simpson(const F& f, double a, double b, double eps, int depth) {
    const double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
    return simpson_refine(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), eps, depth);
}

/// ∫∫ f(x, y) over [x0, x1] × [y0, y1]: adaptive Simpson over x of adaptive Simpson over y
/// (nori's `adaptiveSimpson2D`), each axis started on 4 panels so that a density confined to a
/// sliver of the cell (a cone edge, a triangle corner) is not missed by the first 5 points.
/// Both recursions may go `max_depth` levels deep, so a jump (the rim of a cone, the edge of
/// a triangle) leaves an error of ~2^-max_depth of a panel's mass; only the intervals holding
/// the jump refine that far, and where the pdf is smooth five points per interval suffice.
/// Pdfs computed in single precision have rounding noise that no depth brings under a tight
/// tolerance: grid_test stops at 12 levels (2^-12 of a panel, far below the counts' noise),
/// where 20 took minutes for a Blinn-Phong lobe.
template <class F>
double integrate_2d(const F& f, double x0, double x1, double y0, double y1, double eps, int max_depth = 20) {
    constexpr int kPanels = 4;
    const int kMaxDepth = max_depth;
    const double hx = (x1 - x0) / kPanels, hy = (y1 - y0) / kPanels;
    auto inner = [&](double x) {
        double sum = 0.0;
        for (int k = 0; k < kPanels; ++k) {
            sum += adaptive_simpson([&](double y) { return f(x, y); }, y0 + k * hy, y0 + (k + 1) * hy,
                                    eps / (x1 - x0) / kPanels, kMaxDepth);
        }
        return sum;
    };
    double sum = 0.0;
    for (int k = 0; k < kPanels; ++k) sum += adaptive_simpson(inner, x0 + k * hx, x0 + (k + 1) * hx, eps / kPanels, kMaxDepth);
    return sum;
}

/// A uniform float in [0, 1) from 24 random bits, as glint::Rng makes them.
inline float uniform_float(pcg32& rng) { return static_cast<float>(rng() >> 8) * 0x1p-24f; }

/// Grid coordinates of one sample: nullopt for a rejected sample, NaN for an invalid one.
using GridPoint = std::optional<std::array<double, 2>>;

/// Histograms `samples` draws of `draw` on an nx × ny grid over [x0, x1] × [y0, y1] (cell
/// index ix·ny + iy), integrates `density` over each cell, and runs chi2_test.
template <class Draw, class Density>
Chi2Result grid_test(const Draw& draw, const Density& density, int nx, int ny, double x0, double x1, double y0,
                     double y1, std::size_t samples, uint64_t seed, double significance, int test_count) {
    std::vector<double> observed(static_cast<std::size_t>(nx) * ny, 0.0), expected(observed.size(), 0.0);
    pcg32 rng(seed);
    std::size_t rejected = 0, off_grid = 0;
    // Points a rounding step past the grid's edge (z = 1.0000001) still belong to it.
    constexpr double kSlack = 1e-6;
    for (std::size_t s = 0; s < samples; ++s) {
        const float ux = uniform_float(rng);
        const GridPoint p = draw(Vec2(ux, uniform_float(rng)));
        if (!p) {
            ++rejected;
            continue;
        }
        const double tx = ((*p)[0] - x0) / (x1 - x0), ty = ((*p)[1] - y0) / (y1 - y0);
        if (!(tx >= -kSlack && tx <= 1.0 + kSlack && ty >= -kSlack && ty <= 1.0 + kSlack)) {
            ++off_grid;
            continue;
        }
        const int ix = std::clamp(static_cast<int>(tx * nx), 0, nx - 1);
        const int iy = std::clamp(static_cast<int>(ty * ny), 0, ny - 1);
        observed[static_cast<std::size_t>(ix) * ny + iy] += 1.0;
    }
    const double dx = (x1 - x0) / nx, dy = (y1 - y0) / ny;
    double mass = 0.0;
    for (int ix = 0; ix < nx; ++ix) {
        for (int iy = 0; iy < ny; ++iy) {
            // 1e-9 of probability per cell: a thousandth of a sample at 10^6 samples.
            const double p =
                integrate_2d(density, x0 + ix * dx, x0 + (ix + 1) * dx, y0 + iy * dy, y0 + (iy + 1) * dy, 1e-9, 12);
            mass += p;
            expected[static_cast<std::size_t>(ix) * ny + iy] = p * static_cast<double>(samples);
        }
    }
    Chi2Result result = chi2_test(observed, expected, samples, significance, test_count);
    std::ostringstream out;
    out << nx << "x" << ny << " grid over [" << x0 << ", " << x1 << "] x [" << y0 << ", " << y1 << "], cell = ix*" << ny
        << " + iy; " << rejected << " samples rejected, " << off_grid
        << " off the grid or invalid; the pdf integrates to " << mass << " over the grid\n";
    result.report = out.str() + result.report;
    return result;
}

}  // namespace chi2_detail

/// Cells of `chi2_spherical_grid`: theta_bins × phi_bins, uniform in cos θ over
/// [cos_theta_min, cos_theta_max] (equal solid angle per cell) and in φ over [0, 2π).
struct SphericalGrid {
    int theta_bins = 10;
    int phi_bins = 20;
    double cos_theta_min = -1.0;
    double cos_theta_max = 1.0;
};

/// How many samples, and how strict, for the grid tests.
struct Chi2Options {
    std::size_t samples = 1'000'000;
    uint64_t seed = 1;
    double significance = 0.01;
    int test_count = 1;
};

/// Tests a direction sampler against its solid-angle pdf on a (cos θ, φ) grid, where
/// dω = d(cos θ) dφ. Restricting cos θ to a band resolves narrow lobes and small cones;
/// samples outside the band, rejected samples (nullopt) and directions that are not unit
/// length all land in chi2_test's remainder cell, whose expectation is the pdf mass the
/// grid does not cover.
inline Chi2Result chi2_spherical_grid(const std::function<std::optional<Vec3>(Vec2)>& sample,
                                      const std::function<double(const Vec3&)>& pdf, const SphericalGrid& grid,
                                      const Chi2Options& options = {}) {
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    auto draw = [&](Vec2 u) -> chi2_detail::GridPoint {
        const std::optional<Vec3> w = sample(u);
        if (!w) return std::nullopt;
        if (!is_finite(*w) || std::abs(length(*w) - 1.0f) > 1e-3f) {
            constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
            return std::array{kNaN, kNaN};
        }
        double phi = std::atan2(static_cast<double>(w->y), static_cast<double>(w->x));
        if (phi < 0.0) phi += kTwoPi;
        return std::array{static_cast<double>(w->z), phi};
    };
    auto density = [&](double cos_theta, double phi) {
        const double sin_theta = std::sqrt(std::max(0.0, (1.0 - cos_theta) * (1.0 + cos_theta)));
        return pdf(Vec3(static_cast<float>(sin_theta * std::cos(phi)), static_cast<float>(sin_theta * std::sin(phi)),
                        static_cast<float>(cos_theta)));
    };
    return chi2_detail::grid_test(draw, density, grid.theta_bins, grid.phi_bins, grid.cos_theta_min, grid.cos_theta_max,
                                  0.0, kTwoPi, options.samples, options.seed, options.significance, options.test_count);
}

/// `chi2_spherical_grid` over the whole sphere.
inline Chi2Result chi2_spherical(std::function<std::optional<Vec3>(Vec2)> sample,
                                 std::function<double(const Vec3&)> pdf, int theta_bins = 10, int phi_bins = 20,
                                 std::size_t samples = 1'000'000, uint64_t seed = 1) {
    return chi2_spherical_grid(sample, pdf, {theta_bins, phi_bins, -1.0, 1.0}, {samples, seed, 0.01, 1});
}

/// Tests a sampler of points in the rectangle [lo, hi] against its area density on a
/// bins_x × bins_y grid; rejected samples and points off the rectangle go to the remainder.
inline Chi2Result chi2_planar_grid(const std::function<std::optional<Vec2>(Vec2)>& sample,
                                   const std::function<double(Vec2)>& pdf, Vec2 lo, Vec2 hi, int bins_x, int bins_y,
                                   const Chi2Options& options) {
    auto draw = [&](Vec2 u) -> chi2_detail::GridPoint {
        const std::optional<Vec2> p = sample(u);
        if (!p) return std::nullopt;
        return std::array{static_cast<double>(p->x), static_cast<double>(p->y)};
    };
    auto density = [&](double x, double y) { return pdf(Vec2(static_cast<float>(x), static_cast<float>(y))); };
    return chi2_detail::grid_test(draw, density, bins_x, bins_y, lo.x, hi.x, lo.y, hi.y, options.samples, options.seed,
                                  options.significance, options.test_count);
}

/// `chi2_planar_grid` at significance 0.01 for a single test.
inline Chi2Result chi2_planar(std::function<std::optional<Vec2>(Vec2)> sample, std::function<double(Vec2)> pdf, Vec2 lo,
                              Vec2 hi, int bins_x = 20, int bins_y = 20, std::size_t samples = 1'000'000,
                              uint64_t seed = 1) {
    return chi2_planar_grid(sample, pdf, lo, hi, bins_x, bins_y, {samples, seed, 0.01, 1});
}

}  // namespace glint
