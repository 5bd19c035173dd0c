#pragma once
/// \file A texture looked up at scaled and shifted coordinates (the `uv_scale` and
/// `uv_offset` keys of scene-file textures), so a texture can tile a shape whose own
/// coordinates span [0, 1].

#include "glint/materials/texture.h"

#include <cmath>

namespace glint {

class UvTransformTexture final : public Texture {
public:
    /// Looks `base` up at uv·scale + offset; `base` must outlive this texture.
    UvTransformTexture(const Texture* base, Vec2 scale, Vec2 offset) : base_(base), scale_(scale), offset_(offset) {}
    using Texture::evaluate;
    /// The footprint scales with the coordinates (by the geometric mean of the two scales).
    [[nodiscard]] Color evaluate(const TextureQuery& q) const override {
        return base_->evaluate(TextureQuery{map(q.uv), q.p, q.uv_footprint * std::sqrt(std::abs(scale_.x * scale_.y))});
    }
    [[nodiscard]] float alpha(const Vec2& uv) const override { return base_->alpha(map(uv)); }
    [[nodiscard]] std::string_view type_name() const override { return base_->type_name(); }
    /// A view of the texture it maps, not a texture of its own (not counted by `glint info`).
    [[nodiscard]] bool is_view() const override { return true; }

private:
    [[nodiscard]] Vec2 map(const Vec2& uv) const { return {uv.x * scale_.x + offset_.x, uv.y * scale_.y + offset_.y}; }

    const Texture* base_;
    Vec2 scale_, offset_;
};

}  // namespace glint
