#include "glint/image/film.h"

namespace glint {

Image Film::to_image() const {
    Image img(int(width_), int(height_), 3);
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
        img.pixels[3 * i + 0] = pixels_[i].r;
        img.pixels[3 * i + 1] = pixels_[i].g;
        img.pixels[3 * i + 2] = pixels_[i].b;
    }
    return img;
}

}  // namespace glint
