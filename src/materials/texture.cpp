#include "glint/materials/texture.h"

#include "glint/scene_format/build_context.h"

#include <array>
#include <cmath>

namespace glint {

ImageTexture::ImageTexture(std::shared_ptr<const Image> image, WrapMode wrap, Color scale)
    : image_(image), mip_map_(std::move(image)), wrap_(wrap), scale_(scale) {}

void ImageTexture::lookup(const Vec2& uv, int first, int count, float* out) const {
    sample_bilinear(*image_, uv, wrap_, wrap_, first, count, out);
}

Color ImageTexture::evaluate(const TextureQuery& q) const {
    if (!std::isfinite(q.uv.x) || !std::isfinite(q.uv.y)) return scale_;
    return mip_map_.sample_color(q.uv, q.uv_footprint, wrap_) * scale_;
}

float ImageTexture::alpha(const Vec2& uv) const {
    const int alpha_channel = image_->channels == 2 ? 1 : (image_->channels >= 4 ? 3 : -1);
    if (alpha_channel < 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return 1.0f;
    float a;
    lookup(uv, alpha_channel, 1, &a);
    return a;
}

namespace {

/// ∫₀ˣ s, where the square wave s is +1 on [2k, 2k + 1) and −1 on [2k + 1, 2k + 2): a
/// triangle wave between 0 and 1 of period 2.
double square_wave_integral(double x) {
    const double phase = x - 2.0 * std::floor(x / 2.0);
    return phase < 1.0 ? phase : 2.0 - phase;
}

/// The mean of that square wave over [x − w/2, x + w/2]; the wave itself at w = 0, its mean
/// 0 over an unbounded box (a footprint that overflowed: infinity minus infinity is no number).
double box_filtered_square_wave(double x, double w) {
    if (!(w > 1e-6)) return std::fmod(std::floor(x), 2.0) == 0.0 ? 1.0 : -1.0;
    if (!std::isfinite(w)) return 0.0;
    return (square_wave_integral(x + 0.5 * w) - square_wave_integral(x - 0.5 * w)) / w;
}

}  // namespace

Color CheckerTexture::evaluate(const TextureQuery& q) const {
    if (!std::isfinite(q.uv.x) || !std::isfinite(q.uv.y)) return even_;
    // Square (i, j) is even where the two square waves agree (their product is +1).
    const double w = double(q.uv_footprint) * scale_;
    const double product =
        box_filtered_square_wave(double(q.uv.x) * scale_, w) * box_filtered_square_wave(double(q.uv.y) * scale_, w);
    const auto even_share = float(0.5 * (1.0 + product));
    return even_ * even_share + odd_ * (1.0f - even_share);
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
