// UvTransformTexture: lookups at T·R·S·(u, v, 1), the matrices of the KHR_texture_transform
// README multiplied out here as matrices, and the footprint scaled by sqrt|det| of the linear
// part; the scene file's uv_scale/uv_offset keep their component-wise formula bit for bit.

#include "glint/materials/uv_transform_texture.h"
#include "glint/math/transform.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

using namespace glint;

namespace {

/// Shows where it was looked up: (u, v, footprint) as a colour, and u as alpha.
class WhereTexture final : public Texture {
public:
    using Texture::evaluate;
    [[nodiscard]] Color evaluate(const TextureQuery& q) const override { return {q.uv.x, q.uv.y, q.uv_footprint}; }
    [[nodiscard]] float alpha(const Vec2& uv) const override { return uv.x; }
    [[nodiscard]] std::string_view type_name() const override { return "where"; }
};

/// T·R·S·(u, v, 1) with the README's three 3×3 matrices, as written there, multiplied as
/// 4×4 matrices (the homogeneous 1 in the last row and column, z untouched).
std::array<float, 2> spec_uv(float ox, float oy, float r, float sx, float sy, float u, float v) {
    const float c = std::cos(r), s = std::sin(r);
    const Matrix4 t{{{{1, 0, 0, ox}, {0, 1, 0, oy}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
    const Matrix4 rot{{{{c, s, 0, 0}, {-s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
    const Matrix4 scale{{{{sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
    const Matrix4 m = t * rot * scale;
    return {m.m[0][0] * u + m.m[0][1] * v + m.m[0][3], m.m[1][0] * u + m.m[1][1] * v + m.m[1][3]};
}

}  // namespace

TEST(UvTransformTexture, LooksUpAtTheSpecsTRSProduct) {
    const WhereTexture where;
    const float ox = 0.25f, oy = -0.5f, r = 0.7f, sx = 2.0f, sy = 3.0f;
    const UvTransformTexture view(&where, UvAffineMap::offset_rotation_scale({ox, oy}, r, {sx, sy}));
    int checked = 0;
    for (const Vec2 uv : {Vec2(0.0f, 0.0f), Vec2(1.0f, 0.0f), Vec2(0.0f, 1.0f), Vec2(0.3f, 0.8f), Vec2(-1.5f, 2.25f)}) {
        const auto expected = spec_uv(ox, oy, r, sx, sy, uv.x, uv.y);
        const Color got = view.evaluate(uv, {});
        EXPECT_NEAR(got.r, expected[0], 1e-5) << "u at (" << uv.x << ", " << uv.y << ")";
        EXPECT_NEAR(got.g, expected[1], 1e-5) << "v at (" << uv.x << ", " << uv.y << ")";
        EXPECT_NEAR(view.alpha(uv), expected[0], 1e-5) << "alpha looked up at the mapped u";
        ++checked;
    }
    EXPECT_EQ(checked, 5);
}

TEST(UvTransformTexture, QuarterTurnTakesUToMinusV) {
    // R = [[cos, sin], [−sin, cos]] at π/2: (1, 0) → (0, −1) and (0, 1) → (1, 0).
    const WhereTexture where;
    const float quarter = std::numbers::pi_v<float> / 2;
    const UvTransformTexture view(&where, UvAffineMap::offset_rotation_scale({0.0f, 0.0f}, quarter, {1.0f, 1.0f}));
    const Color u = view.evaluate({1.0f, 0.0f}, {}), v = view.evaluate({0.0f, 1.0f}, {});
    EXPECT_NEAR(u.r, 0.0f, 1e-6f);
    EXPECT_NEAR(u.g, -1.0f, 1e-6f);
    EXPECT_NEAR(v.r, 1.0f, 1e-6f);
    EXPECT_NEAR(v.g, 0.0f, 1e-6f);
}

TEST(UvTransformTexture, FootprintScalesBySqrtOfTheDeterminant) {
    const WhereTexture where;
    const float footprint = 0.01f;
    auto seen = [&](float rotation, Vec2 scale) {
        const UvTransformTexture view(&where, UvAffineMap::offset_rotation_scale({0.3f, 0.1f}, rotation, scale));
        return view.evaluate(TextureQuery{{0.5f, 0.5f}, {}, footprint}).b;
    };
    EXPECT_NEAR(seen(0.9f, {1.0f, 1.0f}), footprint, 1e-8f) << "a rotation keeps areas";
    EXPECT_NEAR(seen(0.0f, {2.0f, 3.0f}), footprint * std::sqrt(6.0f), 1e-8f) << "scale 2×3: sqrt 6";
    EXPECT_NEAR(seen(0.9f, {2.0f, 3.0f}), footprint * std::sqrt(6.0f), 1e-8f) << "turned, still sqrt 6";
    EXPECT_NEAR(seen(0.0f, {-2.0f, 3.0f}), footprint * std::sqrt(6.0f), 1e-8f) << "a mirror keeps the width";
}

TEST(UvTransformTexture, ScaleAndOffsetKeepTheirComponentWiseFormula) {
    // The scene file's uv_scale / uv_offset: exactly uv·scale + offset and footprint
    // × sqrt|sx·sy|, as before the map became affine.
    const WhereTexture where;
    const Vec2 scale(2.5f, -0.3f), offset(0.1f, 0.7f);
    const UvTransformTexture view(&where, scale, offset);
    for (const Vec2 uv : {Vec2(0.123f, 0.987f), Vec2(-3.7f, 11.1f), Vec2(1e-3f, 1e3f)}) {
        const Color got = view.evaluate(TextureQuery{uv, {}, 0.02f});
        EXPECT_EQ(got.r, uv.x * scale.x + offset.x);
        EXPECT_EQ(got.g, uv.y * scale.y + offset.y);
        EXPECT_EQ(got.b, 0.02f * std::sqrt(std::abs(scale.x * scale.y)));
    }
    EXPECT_TRUE(view.is_view());
    EXPECT_EQ(view.type_name(), "where");
}
