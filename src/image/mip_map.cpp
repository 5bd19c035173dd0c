#include "glint/image/mip_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint {

namespace {

/// The source texels output texel i of `count` covers when `n` texels shrink to `count`:
/// [i·s, (i + 1)·s) with s = n / count, each weighted by the part of it inside, over s (a box
/// filter with exact coverage, which keeps the mean for any ratio).
struct Footprint {
    int first = 0;
    std::vector<float> weights;
};

std::vector<Footprint> footprints(int n, int count) {
    std::vector<Footprint> out(static_cast<std::size_t>(count));
    const double step = double(n) / double(count);
    for (int i = 0; i < count; ++i) {
        const double begin = i * step, end = (i + 1) * step;
        out[std::size_t(i)].first = int(begin);
        for (int s = int(begin); s < std::min(int(std::ceil(end)), n); ++s)
            out[std::size_t(i)].weights.push_back(
                float((std::min(end, double(s + 1)) - std::max(begin, double(s))) / step));
    }
    return out;
}

/// `source` resampled to `count` columns (`columns`) or rows, box-filtered as footprints()
/// says. Both passes walk the pixels row by row, so neither strides through memory, and
/// rows are shared out among threads: a 2048×2048 texture's pyramid was 13 % of the CPU
/// time of loading the Khronos TransmissionTest sample. Every output value sums its taps in
/// the same order on any number of threads.
Image shrink(const Image& source, int count, bool columns) {
    const int channels = source.channels;
    Image out(columns ? count : source.width, columns ? source.height : count, channels);
    const std::vector<Footprint> taps = footprints(columns ? source.width : source.height, count);
    constexpr int kRowsPerTask = 16;
    if (columns) {
        tbb::parallel_for(tbb::blocked_range<int>(0, source.height, kRowsPerTask),
                          [&](const tbb::blocked_range<int>& rows) {
                              for (int y = rows.begin(); y < rows.end(); ++y)
                                  for (int i = 0; i < count; ++i) {
                                      const Footprint& f = taps[std::size_t(i)];
                                      for (std::size_t k = 0; k < f.weights.size(); ++k)
                                          for (int c = 0; c < channels; ++c)
                                              out.at(i, y, c) += f.weights[k] * source.at(f.first + int(k), y, c);
                                  }
                          });
        return out;
    }
    const std::size_t row = std::size_t(source.width) * std::size_t(channels);
    tbb::parallel_for(tbb::blocked_range<int>(0, count, kRowsPerTask), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j < rows.end(); ++j) {
            const Footprint& f = taps[std::size_t(j)];
            float* to = &out.pixels[std::size_t(j) * row];
            for (std::size_t k = 0; k < f.weights.size(); ++k) {
                const float* from = &source.pixels[std::size_t(f.first + int(k)) * row];
                for (std::size_t x = 0; x < row; ++x) to[x] += f.weights[k] * from[x];
            }
        }
    });
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
