#include "glint/image/film.h"

namespace glint {

Color Film::at(uint32_t x, uint32_t y) const {
    const Pixel& p = pixels_[std::size_t(y) * width_ + x];
    return p.weight_sum != 0.0f ? p.weighted_sum / p.weight_sum : Color();
}

Image Film::to_image() const {
    Image img(int(width_), int(height_), 3);
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x) {
            const Color c = at(x, y);
            const std::size_t i = std::size_t(y) * width_ + x;
            img.pixels[3 * i + 0] = c.r;
            img.pixels[3 * i + 1] = c.g;
            img.pixels[3 * i + 2] = c.b;
        }
    return img;
}

}  // namespace glint
