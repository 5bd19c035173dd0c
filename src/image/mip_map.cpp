#include "glint/image/mip_map.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

/// `source` resampled to `count` columns (or rows): output column i is the area average of
/// the source over [i·s, (i + 1)·s) with s = source.width / count, texels partly inside
/// weighted by the part (a box filter with exact coverage, which keeps the mean for any ratio).
Image shrink(const Image& source, int count, bool columns) {
    const int n = columns ? source.width : source.height;
    const int across = columns ? source.height : source.width;
    Image out(columns ? count : source.width, columns ? source.height : count, source.channels);
    const double step = double(n) / double(count);
    for (int i = 0; i < count; ++i) {
        const double begin = i * step, end = (i + 1) * step;
        for (int s = int(begin); s < std::min(int(std::ceil(end)), n); ++s) {
            const auto weight = float((std::min(end, double(s + 1)) - std::max(begin, double(s))) / step);
            for (int a = 0; a < across; ++a)
                for (int c = 0; c < source.channels; ++c)
                    (columns ? out.at(i, a, c) : out.at(a, i, c)) +=
                        weight * (columns ? source.at(s, a, c) : source.at(a, s, c));
        }
    }
    return out;
}

}  // namespace

MipMap::MipMap(std::shared_ptr<const Image> image) : base_(std::move(image)) {
    const Image* finer = base_.get();
    while (finer->width > 1 || finer->height > 1) {
        coarser_.push_back(
            shrink(shrink(*finer, std::max(1, finer->width / 2), true), std::max(1, finer->height / 2), false));
        finer = &coarser_.back();
    }
}

float MipMap::level_of_detail(float uv_width) const {
    if (!base_ || !(uv_width > 0.0f)) return 0.0f;
    const float texels = uv_width * float(std::max(base_->width, base_->height));
    const float lod = std::log2(texels);
    return std::isfinite(lod) ? std::clamp(lod, 0.0f, float(levels() - 1)) : (lod > 0.0f ? float(levels() - 1) : 0.0f);
}

Color MipMap::sample_color(const Vec2& uv, float uv_width, WrapMode wrap) const {
    const float lod = level_of_detail(uv_width);
    const auto lower = std::size_t(lod);
    const float t = lod - float(lower);
    const Color fine = sample_bilinear_color(level(lower), uv, wrap, wrap);
    if (t <= 0.0f || lower + 1 >= levels()) return fine;
    return fine * (1.0f - t) + sample_bilinear_color(level(lower + 1), uv, wrap, wrap) * t;
}

}  // namespace glint
