#pragma once
/// \file Textures: colours that vary over a surface.

#include "glint/image/image.h"
#include "glint/image/image_sampling.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <memory>
#include <string_view>

namespace glint {

class BuildContext;
class ParamTable;

class Texture {
public:
    virtual ~Texture() = default;
    /// Linear RGB at texture coordinates `uv` (object-space point `p` for solid textures).
    [[nodiscard]] virtual Color evaluate(const Vec2& uv, const Vec3& p) const = 0;
    /// Coverage in [0, 1] (alpha masks); 1 where the texture has no alpha.
    [[nodiscard]] virtual float alpha(const Vec2& /*uv*/) const { return 1.0f; }
    [[nodiscard]] virtual std::string_view type_name() const = 0;
    /// True for a view of another texture the scene holds (the same image at transformed
    /// coordinates): Scene::texture_count() counts what a scene declares, not its views.
    [[nodiscard]] virtual bool is_view() const { return false; }
};

/// An image looked up with bilinear filtering. v = 0 is the top row of the image
/// (the glTF/OBJ-after-flip convention; loaders flip where their format differs).
class ImageTexture final : public Texture {
public:
    ImageTexture(std::shared_ptr<const Image> image, WrapMode wrap = WrapMode::Repeat, Color scale = Color(1.0f));
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Texture> from_params(const ParamTable& params, BuildContext& context);
    [[nodiscard]] Color evaluate(const Vec2& uv, const Vec3& p) const override;
    [[nodiscard]] float alpha(const Vec2& uv) const override;
    [[nodiscard]] std::string_view type_name() const override { return "image"; }
    [[nodiscard]] const Image& image() const { return *image_; }

private:
    /// Bilinear interpolation of channel range [first, first+count) at uv.
    void lookup(const Vec2& uv, int first, int count, float* out) const;

    std::shared_ptr<const Image> image_;
    WrapMode wrap_;
    Color scale_;
};

/// Alternating squares: `scale` squares per unit of u and v.
class CheckerTexture final : public Texture {
public:
    CheckerTexture(Color even, Color odd, float scale) : even_(even), odd_(odd), scale_(scale) {}
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::unique_ptr<Texture> from_params(const ParamTable& params, BuildContext& context);
    [[nodiscard]] Color evaluate(const Vec2& uv, const Vec3& p) const override;
    [[nodiscard]] std::string_view type_name() const override { return "checker"; }

private:
    Color even_, odd_;
    float scale_;
};

}  // namespace glint
