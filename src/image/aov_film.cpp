#include "glint/image/aov_film.h"

#include "glint/math/constants.h"

#include <algorithm>
#include <stdexcept>

namespace glint {

void AovFilm::add_sample(uint32_t x, uint32_t y, const FirstHit& first, const Color& radiance) {
    AovPixel& p = pixels_[std::size_t(y) * width_ + x];
    ++p.samples;
    const float values[3] = {radiance.r, radiance.g, radiance.b};
    for (int c = 0; c < 3; ++c) {
        p.radiance[c] += values[c];
        p.radiance_squared[c] += double(values[c]) * values[c];
    }
    if (!first.hit) return;
    ++p.hits;
    p.albedo += first.albedo;
    p.normal += first.normal;
    p.position += first.position;
    p.distance += first.distance;
}

namespace {

/// The values of `aov` at pixel `p`, as many as its channels.
void aov_values(Aov aov, const AovPixel& p, float* out) {
    const float n = p.samples > 0 ? float(p.samples) : 1.0f;
    auto put = [&](float a, float b, float c) {
        out[0] = a;
        out[1] = b;
        out[2] = c;
    };
    switch (aov) {
        case Aov::Albedo:
            put(p.albedo.r / n, p.albedo.g / n, p.albedo.b / n);
            return;
        case Aov::Normal:
            put(p.normal.x / n, p.normal.y / n, p.normal.z / n);
            return;
        case Aov::Position:
            put(p.position.x / n, p.position.y / n, p.position.z / n);
            return;
        case Aov::Depth:
            out[0] = p.hits > 0 ? p.distance / float(p.hits) : kInfinity;
            return;
        case Aov::Spp:
            out[0] = float(p.samples);
            return;
        case Aov::Variance:
            // The unbiased sample variance s² = (Σx² − (Σx)²/n)/(n − 1), divided by n: the
            // variance of the mean. Zero for a pixel of fewer than two samples.
            for (int c = 0; c < 3; ++c) {
                const double k = p.samples;
                const double s2 =
                    k > 1 ? std::max(0.0, (p.radiance_squared[c] - p.radiance[c] * p.radiance[c] / k) / (k - 1)) : 0.0;
                out[c] = k > 1 ? float(s2 / k) : 0.0f;
            }
            return;
    }
}

}  // namespace

Image AovFilm::append_to(const Image& image) const {
    if (image.channel_names.size() != std::size_t(image.channels))
        throw std::invalid_argument("AovFilm::append_to: the image's channels have no names");
    std::vector<std::string> names = image.channel_names;
    std::vector<std::size_t> widths;  // channels per AOV
    for (const Aov aov : aovs_) {
        std::vector<std::string> channels = aov_channels(aov);
        widths.push_back(channels.size());
        for (std::string& name : channels) names.push_back(std::move(name));
    }
    Image out(image.width, image.height, int(names.size()));
    out.channel_names = std::move(names);
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x) {
            const std::size_t pixel = std::size_t(y) * width_ + x;
            const float* in = &image.pixels[pixel * std::size_t(image.channels)];
            float* dst = &out.pixels[pixel * std::size_t(out.channels)];
            std::copy(in, in + image.channels, dst);
            dst += image.channels;
            for (std::size_t a = 0; a < aovs_.size(); ++a) {
                aov_values(aovs_[a], pixels_[pixel], dst);
                dst += widths[a];
            }
        }
    return out;
}

}  // namespace glint
