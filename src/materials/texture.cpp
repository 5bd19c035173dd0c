#include "glint/materials/texture.h"

#include "glint/scene_format/build_context.h"

#include <array>
#include <cmath>

namespace glint {

ImageTexture::ImageTexture(std::shared_ptr<const Image> image, WrapMode wrap, Color scale)
    : image_(std::move(image)), wrap_(wrap), scale_(scale) {}

void ImageTexture::lookup(const Vec2& uv, int first, int count, float* out) const {
    sample_bilinear(*image_, uv, wrap_, wrap_, first, count, out);
}

Color ImageTexture::evaluate(const Vec2& uv, const Vec3&) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return scale_;
    return sample_bilinear_color(*image_, uv, wrap_, wrap_) * scale_;
}

float ImageTexture::alpha(const Vec2& uv) const {
    const int alpha_channel = image_->channels == 2 ? 1 : (image_->channels >= 4 ? 3 : -1);
    if (alpha_channel < 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return 1.0f;
    float a;
    lookup(uv, alpha_channel, 1, &a);
    return a;
}

Color CheckerTexture::evaluate(const Vec2& uv, const Vec3&) const {
    const auto i = static_cast<int64_t>(std::floor(uv.x * scale_));
    const auto j = static_cast<int64_t>(std::floor(uv.y * scale_));
    return ((i + j) & 1) == 0 ? even_ : odd_;
}

std::unique_ptr<Texture> ImageTexture::from_params(const ParamTable& t, BuildContext& context) {
    constexpr std::array<std::string_view, 2> kEncodings{"color", "data"};
    constexpr std::array<std::string_view, 2> kWrapModes{"repeat", "clamp"};
    const bool data = t.choice("encoding", kEncodings, "color") == "data";
    auto image = context.image(t, "file", data ? ColorEncoding::Data : ColorEncoding::Color);
    const WrapMode wrap = t.choice("wrap", kWrapModes, "repeat") == "clamp" ? WrapMode::Clamp : WrapMode::Repeat;
    return std::make_unique<ImageTexture>(std::move(image), wrap, t.color("tint", Color(1.0f)));
}

std::unique_ptr<Texture> CheckerTexture::from_params(const ParamTable& t, BuildContext&) {
    const float scale = t.number("scale", 1.0f);
    if (!(scale > 0.0f)) t.fail("scale", "a positive number of squares per unit of u and v");
    return std::make_unique<CheckerTexture>(t.color("even", Color(0.9f)), t.color("odd", Color(0.1f)), scale);
}

}  // namespace glint
