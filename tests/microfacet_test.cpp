// The GGX distribution: normalisation of D and of the visible normals, Smith's masking, and
// a chi-square test of the visible-normal sampler against its density (tests/chi2.h).

#include "chi2.h"

#include "glint/materials/microfacet.h"
#include "glint/math/constants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>

using namespace glint;

namespace {

const Vec3 kUp(0.0f, 0.0f, 1.0f);

// The chi-square tests below form one family (Šidák-corrected to 1% in all).
constexpr int kChi2Tests = 12;

Vec3 from_polar(float theta_degrees, float phi_degrees = 0.0f) {
    const float t = radians(theta_degrees), p = radians(phi_degrees);
    return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

/// ∫ f dω over the directions with cos θ in [z0, z1], in (cos θ, φ) where dω = d(cos θ) dφ.
double integrate_band(const std::function<double(const Vec3&)>& f, double z0, double z1) {
    return chi2_detail::integrate_2d(
        [&](double c, double phi) {
            const double s = std::sqrt(std::max(0.0, (1.0 - c) * (1.0 + c)));
            return f(Vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(c)));
        },
        z0, z1, 0.0, 2.0 * std::numbers::pi, 1e-5, 16);
}

struct Alphas {
    float x, y;
};
std::ostream& operator<<(std::ostream& os, const Alphas& a) { return os << "alpha (" << a.x << ", " << a.y << ")"; }

}  // namespace

// ---- The distribution --------------------------------------------------------------------

TEST(TrowbridgeReitz, ProjectedNormalDensityIntegratesToOne) {
    // ∫ D(wm) cos θm dωm = 1: the microfacets' projected area is the macrosurface's.
    for (const Alphas a : {Alphas{0.05f, 0.05f}, Alphas{0.3f, 0.3f}, Alphas{1.0f, 1.0f}, Alphas{0.1f, 0.5f}}) {
        const TrowbridgeReitz d(a.x, a.y);
        const double total = integrate_band([&](const Vec3& wm) { return double(d.D(wm)) * wm.z; }, 0.0, 1.0);
        EXPECT_NEAR(total, 1.0, 1e-3) << a;
    }
}

TEST(TrowbridgeReitz, VisibleNormalDensityIntegratesToOne) {
    int checked = 0;
    for (const Alphas a : {Alphas{0.2f, 0.2f}, Alphas{0.8f, 0.8f}, Alphas{0.1f, 0.6f}}) {
        const TrowbridgeReitz d(a.x, a.y);
        // Also from under the surface (the mirror image's visible normals) and near grazing.
        for (const Vec3 w :
             {from_polar(0.0f), from_polar(45.0f, 30.0f), from_polar(85.0f, 120.0f), from_polar(130.0f, 200.0f)}) {
            const double total = integrate_band([&](const Vec3& wm) { return double(d.D(w, wm)); }, 0.0, 1.0);
            EXPECT_NEAR(total, 1.0, 2e-3) << a << ", w = " << w;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 12);
}

TEST(TrowbridgeReitz, SmithMaskingMatchesItsClosedFormAndIsOneAtTheNormal) {
    const TrowbridgeReitz d(0.4f, 0.4f);
    EXPECT_FLOAT_EQ(d.G1(kUp), 1.0f);
    EXPECT_EQ(d.G1(Vec3(1.0f, 0.0f, 0.0f)), 0.0f) << "a grazing direction sees no microfacet";
    // Isotropic Smith-GGX, Walter et al. 2007 eq. 34: G1 = 2 / (1 + √(1 + α² tan²θ)).
    const float theta = radians(60.0f), alpha = 0.4f;
    const float expected = 2.0f / (1.0f + std::sqrt(1.0f + alpha * alpha * std::tan(theta) * std::tan(theta)));
    EXPECT_NEAR(d.G1(from_polar(60.0f, 77.0f)), expected, 1e-6f);
    // Height-correlated: G = 1/(1 + Λo + Λi) ≥ G1(wo)·G1(wi) (Heitz 2014, §6).
    const Vec3 wo = from_polar(60.0f), wi = from_polar(40.0f, 180.0f);
    EXPECT_GE(d.G(wo, wi), d.G1(wo) * d.G1(wi));
    EXPECT_LE(d.G(wo, wi), std::min(d.G1(wo), d.G1(wi)));
}

TEST(MicrofacetChi2, VisibleNormalSamplesFollowTheirDensity) {
    const struct {
        Alphas alpha;
        double cos_min;  // a band that holds the lobe, so that its cells resolve it
    } cases[] = {{{0.2f, 0.2f}, 0.6}, {{0.6f, 0.6f}, 0.0}, {{1.0f, 1.0f}, 0.0}, {{0.15f, 0.6f}, 0.0}};
    for (const auto& c : cases) {
        const TrowbridgeReitz d(c.alpha.x, c.alpha.y);
        for (const Vec3 w : {from_polar(0.0f), from_polar(50.0f, 40.0f), from_polar(85.0f, 250.0f)}) {
            const Chi2Result r = chi2_spherical_grid([&](Vec2 u) { return std::optional<Vec3>(d.sample_wm(w, u)); },
                                                     [&](const Vec3& wm) { return double(d.pdf(w, wm)); },
                                                     {12, 24, c.cos_min, 1.0}, {300'000, 11, 0.01, kChi2Tests});
            EXPECT_TRUE(r.passed) << c.alpha << ", w = " << w << "\n" << r.report;
        }
    }
}
