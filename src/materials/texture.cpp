#include "glint/materials/texture.h"

#include <cmath>

namespace glint {

ImageTexture::ImageTexture(std::shared_ptr<const Image> image, WrapMode wrap, Color scale)
    : image_(std::move(image)), wrap_(wrap), scale_(scale) {}

void ImageTexture::lookup(const Vec2& uv, int first, int count, float* out) const {
    const Image& img = *image_;
    // Texel centres sit at half-integer coordinates.
    const float x = uv.x * float(img.width) - 0.5f;
    const float y = uv.y * float(img.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    auto wrap = [&](int i, int n) {
        if (wrap_ == WrapMode::Clamp) return std::clamp(i, 0, n - 1);
        const int m = i % n;
        return m < 0 ? m + n : m;
    };
    const int x0 = wrap(int(fx), img.width), x1 = wrap(int(fx) + 1, img.width);
    const int y0 = wrap(int(fy), img.height), y1 = wrap(int(fy) + 1, img.height);
    for (int k = 0; k < count; ++k) {
        const int c = first + k;
        const float top = img.at(x0, y0, c) * (1.0f - tx) + img.at(x1, y0, c) * tx;
        const float bottom = img.at(x0, y1, c) * (1.0f - tx) + img.at(x1, y1, c) * tx;
        out[k] = top * (1.0f - ty) + bottom * ty;
    }
}

Color ImageTexture::evaluate(const Vec2& uv, const Vec3&) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return scale_;
    float rgb[3];
    if (image_->channels >= 3) {
        lookup(uv, 0, 3, rgb);
        return Color(rgb[0], rgb[1], rgb[2]) * scale_;
    }
    lookup(uv, 0, 1, rgb);
    return Color(rgb[0]) * scale_;
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

}  // namespace glint
