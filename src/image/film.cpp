#include "glint/image/film.h"

namespace glint {

Color Film::at(uint32_t x, uint32_t y) const {
    const FilmPixel& p = pixels_[std::size_t(y) * width_ + x];
    return p.weight_sum != 0.0f ? p.weighted_sum / p.weight_sum : Color();
}

Image Film::to_image(bool sample_counts) const {
    const int channels = sample_counts ? 4 : 3;
    Image img(int(width_), int(height_), channels);
    img.channel_names = {"R", "G", "B"};
    if (sample_counts) img.channel_names.emplace_back("samples");
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x) {
            const Color c = at(x, y);
            float* out = &img.pixels[(std::size_t(y) * width_ + x) * channels];
            out[0] = c.r;
            out[1] = c.g;
            out[2] = c.b;
            if (sample_counts) out[3] = float(samples_at(x, y));
        }
    return img;
}

}  // namespace glint
