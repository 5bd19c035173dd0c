// EnvironmentLight: importance sampling of equirect, sphere and angular maps against its own
// solid-angle pdf (chi-square, tests/chi2.h), the pdf integrating to 1 over the sphere, a
// uniform map sampled uniformly (the layout's Jacobian), and a constant colour.

#include "glint/lights/environment_light.h"
#include "chi2.h"
#include "glint/math/constants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>

using namespace glint;

namespace {

constexpr BackgroundKind kMaps[] = {BackgroundKind::Equirectangular, BackgroundKind::SphereMap,
                                    BackgroundKind::AngularMap};

/// A synthetic map of the layout's shape (2:1 or square): a smooth gradient, a dark band and
/// a small bright "sun" of a few pixels, so that the density spans three orders of magnitude.
std::shared_ptr<const Image> synthetic_map(BackgroundKind kind, bool uniform = false) {
    const int h = 16, w = kind == BackgroundKind::Equirectangular ? 32 : 16;
    Image img(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float v = uniform ? 1.0f : 0.2f + float(x) / float(w) + (y == h / 2 ? -0.15f : 0.0f);
            if (!uniform && x >= w / 4 && x < w / 4 + 2 && y >= h / 4 && y < h / 4 + 2) v = 200.0f;
            for (int c = 0; c < 3; ++c) img.at(x, y, c) = v * (c == 2 ? 0.5f : 1.0f);
        }
    return std::make_shared<const Image>(std::move(img));
}

std::unique_ptr<EnvironmentLight> light_of(BackgroundKind kind, float rotation = 0.0f, bool uniform = false) {
    return EnvironmentLight::of(Background::environment(kind, synthetic_map(kind, uniform), rotation, 2.0f));
}

const char* name(BackgroundKind kind) {
    return kind == BackgroundKind::Equirectangular ? "equirect"
           : kind == BackgroundKind::SphereMap     ? "spheremap"
                                                   : "angmap";
}

TEST(EnvironmentLight, Chi2SamplesFollowThePdf) {
    for (const BackgroundKind kind : kMaps) {
        // An angular map's density grows as 1/angle towards +z, which its whole rim shows:
        // integrable, but no cell integration near it is accurate, so the grid stops short of
        // it (the samples beyond go to the remainder cell, expected 1 − the grid's mass).
        const bool angular = kind == BackgroundKind::AngularMap;
        const auto light = light_of(kind, angular ? 0.0f : 30.0f);
        ASSERT_TRUE(light);
        const Chi2Result r = chi2_spherical_grid(
            [&](Vec2 u) -> std::optional<Vec3> {
                const LightSample ls = light->sample(Vec3(0.0f), u);
                if (!(ls.pdf > 0.0f)) return std::nullopt;
                return ls.direction;
            },
            [&](const Vec3& d) { return double(light->pdf_direction(d, Vec3(0.0f))); },
            {16, 32, -1.0, angular ? 0.7 : 1.0}, {1'000'000, 7, 0.01, 3});
        EXPECT_TRUE(r.passed) << name(kind) << ": " << r.report;
    }
}

TEST(EnvironmentLight, SampleAgreesWithPdfAndRadiance) {
    for (const BackgroundKind kind : kMaps) {
        const auto light = light_of(kind, 30.0f);
        const Background bg = Background::environment(kind, synthetic_map(kind), 30.0f, 2.0f);
        int valid = 0;
        for (int i = 0; i < 64; ++i)
            for (int j = 0; j < 64; ++j) {
                const LightSample ls = light->sample(Vec3(1.0f, 2.0f, 3.0f), Vec2((i + 0.5f) / 64, (j + 0.5f) / 64));
                if (!(ls.pdf > 0.0f)) continue;
                ++valid;
                EXPECT_FALSE(ls.is_delta);
                EXPECT_EQ(ls.distance, kInfinity);
                EXPECT_NEAR(light->pdf_direction(ls.direction, Vec3(0.0f)) / ls.pdf, 1.0f, 2e-3f) << name(kind);
                EXPECT_EQ(ls.radiance, bg.evaluate(ls.direction)) << name(kind);
            }
        EXPECT_GT(valid, 64 * 64 * 9 / 10) << name(kind);
    }
}

/// ∫ pdf dω by the midpoint rule on a fine (cos θ, φ) grid.
double pdf_integral(const Light& light) {
    constexpr int kCos = 600, kPhi = 1200;
    double sum = 0.0;
    for (int i = 0; i < kCos; ++i) {
        const double z = -1.0 + (i + 0.5) * 2.0 / kCos, r = std::sqrt(1.0 - z * z);
        for (int j = 0; j < kPhi; ++j) {
            const double phi = (j + 0.5) * 2.0 * kPi / kPhi;
            sum += light.pdf_direction(Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)), Vec3(0.0f));
        }
    }
    return sum * (2.0 / kCos) * (2.0 * kPi / kPhi);
}

TEST(EnvironmentLight, PdfIntegratesToOne) {
    for (const BackgroundKind kind : kMaps) {
        // A disk-shaped map loses the parts of its rim pixels that lie off the disk (their
        // samples are rejected): about 1/width of the mass here.
        const double tolerance = kind == BackgroundKind::Equirectangular ? 5e-3 : 0.04;
        EXPECT_NEAR(pdf_integral(*light_of(kind, 30.0f)), 1.0, tolerance) << name(kind);
    }
    const auto sky = EnvironmentLight::of(Background::constant(Color(0.3f, 0.5f, 0.9f)));
    EXPECT_NEAR(pdf_integral(*sky), 1.0, 1e-4);
}

TEST(EnvironmentLight, AUniformMapIsSampledUniformly) {
    // Weights are luminance × the pixel's solid angle: a map of one radiance must give every
    // direction the same density 1/(4π) (drop sin θ or the angmap's Jacobian and it does not).
    for (const BackgroundKind kind : kMaps) {
        const auto light = light_of(kind, 0.0f, true);
        for (Vec3 d : {Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(0.3f, 0.8f, 0.2f), Vec3(-0.5f, -0.7f, 0.4f),
                       Vec3(0.2f, 0.1f, 0.9f)}) {
            d = normalize(d);
            EXPECT_NEAR(light->pdf_direction(d, Vec3(0.0f)) * 4.0f * kPi, 1.0f, 0.15f)
                << name(kind) << " direction " << d;
        }
    }
}

TEST(EnvironmentLight, ConstantColourAndBlackBackgrounds) {
    const auto sky = EnvironmentLight::of(Background::constant(Color(0.3f, 0.5f, 0.9f)));
    ASSERT_TRUE(sky);
    const LightSample ls = sky->sample(Vec3(0.0f), Vec2(0.3f, 0.7f));
    EXPECT_EQ(ls.radiance, Color(0.3f, 0.5f, 0.9f));
    EXPECT_FLOAT_EQ(ls.pdf, 0.25f * kInvPi);
    // At a surface, cosine-weighted about its normal: every sample above it, with cos θ/π.
    const Vec3 n = normalize(Vec3(0.3f, 0.9f, -0.2f));
    for (int i = 0; i < 16; ++i) {
        const LightSample s = sky->sample_at_surface(Vec3(0.0f), n, Vec2((i + 0.5f) / 16, (i * 7 % 16 + 0.5f) / 16));
        EXPECT_GT(dot(s.direction, n), 0.0f);
        EXPECT_NEAR(s.pdf, dot(s.direction, n) * kInvPi, 1e-5f);
        EXPECT_FLOAT_EQ(sky->pdf_direction(s.direction, n), s.pdf);
    }
    EXPECT_EQ(sky->pdf_direction(-n, n), 0.0f);
    EXPECT_FALSE(EnvironmentLight::of(Background::constant(Color(0.0f))));
    EXPECT_FALSE(EnvironmentLight::of(Background()));
    auto black = std::make_shared<const Image>(Image(8, 4, 3));
    EXPECT_FALSE(EnvironmentLight::of(Background::environment(BackgroundKind::Equirectangular, black)));
}

}  // namespace
