#include "glint/image/image_sampling.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

/// Texel index of the (floored) coordinate f on an axis of n texels. Wrapping happens in
/// float, so uv far outside [0, 1] cannot overflow the int conversion.
int texel_index(float f, int n, WrapMode mode) {
    if (mode == WrapMode::Clamp) return static_cast<int>(std::clamp(f, 0.0f, float(n - 1)));
    float m = std::fmod(f, float(n));
    if (m < 0.0f) m += float(n);
    return std::min(static_cast<int>(m), n - 1);
}

}  // namespace

void sample_bilinear(const Image& img, const Vec2& uv, WrapMode wrap_u, WrapMode wrap_v, int first, int count,
                     float* out) {
    const float x = uv.x * float(img.width) - 0.5f;
    const float y = uv.y * float(img.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    const int x0 = texel_index(fx, img.width, wrap_u), x1 = texel_index(fx + 1.0f, img.width, wrap_u);
    const int y0 = texel_index(fy, img.height, wrap_v), y1 = texel_index(fy + 1.0f, img.height, wrap_v);
    for (int k = 0; k < count; ++k) {
        const int c = first + k;
        const float top = img.at(x0, y0, c) * (1.0f - tx) + img.at(x1, y0, c) * tx;
        const float bottom = img.at(x0, y1, c) * (1.0f - tx) + img.at(x1, y1, c) * tx;
        out[k] = top * (1.0f - ty) + bottom * ty;
    }
}

Color sample_bilinear_color(const Image& image, const Vec2& uv, WrapMode wrap_u, WrapMode wrap_v) {
    float rgb[3];
    if (image.channels >= 3) {
        sample_bilinear(image, uv, wrap_u, wrap_v, 0, 3, rgb);
        return {rgb[0], rgb[1], rgb[2]};
    }
    sample_bilinear(image, uv, wrap_u, wrap_v, 0, 1, rgb);
    return Color(rgb[0]);
}

}  // namespace glint
