#pragma once
/// \file A texture looked up at affinely mapped coordinates: the `uv_scale` and `uv_offset`
/// keys of scene-file textures (so a texture can tile a shape whose own coordinates span
/// [0, 1]), and glTF's KHR_texture_transform (offset, rotation, scale).

#include "glint/materials/texture.h"

#include <cmath>

namespace glint {

/// The affine map uv' = A·uv + t, as the top two rows of a 3×3 matrix acting on (u, v, 1).
struct UvAffineMap {
    /// Row-major: u' = m[0][0]·u + m[0][1]·v + m[0][2], v' = m[1][0]·u + m[1][1]·v + m[1][2].
    float m[2][3] = {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};

    /// uv·scale + offset, component-wise.
    [[nodiscard]] static UvAffineMap scale_offset(Vec2 scale, Vec2 offset) {
        return {{{scale.x, 0.0f, offset.x}, {0.0f, scale.y, offset.y}}};
    }
    /// T·R·S of the KHR_texture_transform spec: S scales by `scale`, R turns by `rotation`
    /// radians with R = [[cos, sin], [−sin, cos]] (counter-clockwise as an image is seen,
    /// v pointing down), T shifts by `offset`.
    [[nodiscard]] static UvAffineMap offset_rotation_scale(Vec2 offset, float rotation, Vec2 scale) {
        // In double, so that rotation 0 gives cos 1 and sin 0 exactly and π/2 its float-nearest.
        const float c = float(std::cos(double(rotation))), s = float(std::sin(double(rotation)));
        return {{{c * scale.x, s * scale.y, offset.x}, {-s * scale.x, c * scale.y, offset.y}}};
    }

    /// The mapped point. Written as u·a + (v·b + c) so that a scale-only map (b = 0) gives
    /// the very bits of u·a + c, the `uv_scale`/`uv_offset` formula before the map was affine.
    [[nodiscard]] Vec2 operator()(const Vec2& uv) const {
        return {uv.x * m[0][0] + (uv.y * m[0][1] + m[0][2]), uv.y * m[1][1] + (uv.x * m[1][0] + m[1][2])};
    }
    /// How the map scales widths: sqrt|det A|, the geometric mean of A's singular values (a
    /// circle of diameter w becomes an ellipse of the same area as a circle of diameter
    /// w·sqrt|det A|); rotations leave it 1, a scale (sx, sy) makes it sqrt|sx·sy|.
    [[nodiscard]] float linear_scale() const { return std::sqrt(std::abs(m[0][0] * m[1][1] - m[0][1] * m[1][0])); }
    [[nodiscard]] bool operator==(const UvAffineMap& other) const = default;
};

class UvTransformTexture final : public Texture {
public:
    /// Looks `base` up at map(uv); `base` must outlive this texture.
    UvTransformTexture(const Texture* base, const UvAffineMap& map) : base_(base), map_(map) {}
    /// Looks `base` up at uv·scale + offset (the scene file's `uv_scale`, `uv_offset`).
    UvTransformTexture(const Texture* base, Vec2 scale, Vec2 offset)
        : UvTransformTexture(base, UvAffineMap::scale_offset(scale, offset)) {}
    using Texture::evaluate;
    /// The footprint scales with the coordinates, by UvAffineMap::linear_scale().
    [[nodiscard]] Color evaluate(const TextureQuery& q) const override {
        return base_->evaluate(TextureQuery{map_(q.uv), q.p, q.uv_footprint * map_.linear_scale()});
    }
    [[nodiscard]] float alpha(const Vec2& uv) const override { return base_->alpha(map_(uv)); }
    [[nodiscard]] std::string_view type_name() const override { return base_->type_name(); }
    [[nodiscard]] int channel_count() const override { return base_->channel_count(); }
    /// A view of the texture it maps, not a texture of its own (not counted by `glint info`).
    [[nodiscard]] bool is_view() const override { return true; }
    /// The map applied to lookup coordinates.
    [[nodiscard]] const UvAffineMap& map() const { return map_; }

private:
    const Texture* base_;
    UvAffineMap map_;
};

}  // namespace glint
