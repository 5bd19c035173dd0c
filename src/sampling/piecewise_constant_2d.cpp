#include "glint/sampling/piecewise_constant_2d.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace glint {

namespace {

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

std::vector<float> row_sums(std::span<const float> weights, int width, int height) {
    if (width <= 0 || height <= 0 || weights.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("PiecewiseConstant2D: expected width × height weights");
    std::vector<float> sums(std::size_t(height), 0.0f);
    tbb::parallel_for(0, height, [&](int y) {
        double sum = 0.0;
        for (int x = 0; x < width; ++x) sum += double(weights[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
        sums[std::size_t(y)] = float(sum);
    });
    return sums;
}

/// The cell of coordinate c in [0, 1] on an axis of n cells.
int cell(float c, int n) { return std::clamp(int(c * float(n)), 0, n - 1); }

}  // namespace

PiecewiseConstant2D::PiecewiseConstant2D(std::span<const float> weights, int width, int height)
    : width_(width), height_(height), rows_(row_sums(weights, width, height)) {
    // Each row's distribution is built on whichever thread takes it, then moved into place in
    // row order; a row's weights refused (negative, NaN) rethrow on this thread.
    std::vector<std::optional<DiscreteDistribution>> built(static_cast<std::size_t>(height));
    tbb::parallel_for(0, height, [&](int y) {
        const auto first = weights.begin() + std::ptrdiff_t(y) * width;
        std::vector<float> row(first, first + width);
        if (rows_.pmf(std::size_t(y)) == 0.0f) std::fill(row.begin(), row.end(), 1.0f);
        built[std::size_t(y)].emplace(std::move(row));
    });
    columns_.reserve(std::size_t(height));
    for (std::optional<DiscreteDistribution>& row : built) columns_.push_back(std::move(*row));
}

Vec2 PiecewiseConstant2D::sample(Vec2 u, float* pdf) const {
    float row_pmf = 0.0f, column_pmf = 0.0f, v_within = 0.0f, u_within = 0.0f;
    const std::size_t y = rows_.sample(u.y, &row_pmf, &v_within);
    const std::size_t x = columns_[y].sample(u.x, &column_pmf, &u_within);
    *pdf = row_pmf * column_pmf * float(width_) * float(height_);
    return {std::min((float(x) + u_within) / float(width_), kOneMinusEpsilon),
            std::min((float(y) + v_within) / float(height_), kOneMinusEpsilon)};
}

float PiecewiseConstant2D::pdf(Vec2 p) const {
    const auto x = std::size_t(cell(p.x, width_)), y = std::size_t(cell(p.y, height_));
    return rows_.pmf(y) * columns_[y].pmf(x) * float(width_) * float(height_);
}

}  // namespace glint
