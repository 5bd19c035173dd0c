#pragma once
/// \file Textures: colours that vary over a surface.

#include "glint/image/image.h"
#include "glint/image/image_sampling.h"
#include "glint/image/mip_map.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <memory>
#include <string_view>

namespace glint {

class BuildContext;
class ParamTable;

/// Where a texture is looked up, and over how much of it.
struct TextureQuery {
    Vec2 uv;
    /// The point, for solid textures.
    Vec3 p;
    /// The width, in units of uv, of the region a pixel sample covers there (the ray cone's
    /// footprint, integrators/ray_cone.h): a filtered texture averages over it. 0: a point.
    float uv_footprint = 0.0f;
};

class Texture {
public:
    virtual ~Texture() = default;
    /// Linear RGB over the footprint of `q`.
    [[nodiscard]] virtual Color evaluate(const TextureQuery& q) const = 0;
    /// Linear RGB at the point `uv` (object-space point `p` for solid textures).
    [[nodiscard]] Color evaluate(const Vec2& uv, const Vec3& p) const { return evaluate(TextureQuery{uv, p, 0.0f}); }
    /// Coverage in [0, 1] (alpha masks); 1 where the texture has no alpha.
    [[nodiscard]] virtual float alpha(const Vec2& /*uv*/) const { return 1.0f; }
    /// The channels the texture holds: an image's own count, 3 for colours made up.
    [[nodiscard]] virtual int channel_count() const { return 3; }
    [[nodiscard]] virtual std::string_view type_name() const = 0;
    /// True for a view of another texture the scene holds (the same image at transformed
    /// coordinates): Scene::texture_count() counts what a scene declares, not its views.
    [[nodiscard]] virtual bool is_view() const { return false; }
};

/// An image, filtered trilinearly over a MIP pyramid (image/mip_map.h): bilinear in the two
/// levels whose texel size brackets the footprint, blended by the fraction between them
/// (Williams 1983), so that a texture seen from afar averages instead of aliasing. v = 0 is
/// the top row of the image (the glTF/OBJ-after-flip convention; loaders flip where their
/// format differs). The alpha channel is looked up in the full-resolution image: cut-outs
/// keep their edges.
class ImageTexture final : public Texture {
public:
    ImageTexture(std::shared_ptr<const Image> image, WrapMode wrap = WrapMode::Repeat, Color scale = Color(1.0f));
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Texture> from_params(const ParamTable& params, BuildContext& context);
    using Texture::evaluate;
    [[nodiscard]] Color evaluate(const TextureQuery& q) const override;
    [[nodiscard]] float alpha(const Vec2& uv) const override;
    [[nodiscard]] std::string_view type_name() const override { return "image"; }
    [[nodiscard]] int channel_count() const override { return image_->channels; }
    [[nodiscard]] const Image& image() const { return *image_; }

private:
    /// Bilinear interpolation of channel range [first, first+count) at uv.
    void lookup(const Vec2& uv, int first, int count, float* out) const;

    std::shared_ptr<const Image> image_;
    MipMap mip_map_;
    WrapMode wrap_;
    Color scale_;
};

/// Alternating squares: `scale` squares per unit of u and v. A lookup with a footprint is
/// the exact average of the squares over a box that wide (the closed-form box-filtered
/// checkerboard: the filter is separable, so the average of the ±1 product of two square
/// waves is the product of their averages, each a difference of a triangle wave).
class CheckerTexture final : public Texture {
public:
    CheckerTexture(Color even, Color odd, float scale) : even_(even), odd_(odd), scale_(scale) {}
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Texture> from_params(const ParamTable& params, BuildContext& context);
    using Texture::evaluate;
    [[nodiscard]] Color evaluate(const TextureQuery& q) const override;
    [[nodiscard]] std::string_view type_name() const override { return "checker"; }

private:
    Color even_, odd_;
    float scale_;
};

}  // namespace glint
