#pragma once
/// \file A MIP pyramid (Williams 1983, "Pyramidal Parametrics"): an image and copies of it
/// halved again and again down to one texel, each texel the exact area average of the finer
/// level's texels it covers, looked up trilinearly for a footprint width.

#include "glint/image/image.h"
#include "glint/image/image_sampling.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"

#include <memory>
#include <vector>

namespace glint {

class MipMap {
public:
    MipMap() = default;
    /// The pyramid of `image` (level 0, shared, not copied): each level is ⌊half⌋ the size of
    /// the one before on each axis (at least 1), down to 1×1. Odd sizes are resampled with
    /// exact fractional box weights, so every level keeps the image's mean.
    explicit MipMap(std::shared_ptr<const Image> image);

    /// Levels, the full-resolution image included.
    [[nodiscard]] std::size_t levels() const { return coarser_.size() + 1; }
    /// Level `i`: 0 is the image itself.
    [[nodiscard]] const Image& level(std::size_t i) const { return i == 0 ? *base_ : coarser_[i - 1]; }

    /// The level of detail for a footprint `uv_width` wide: log2 of how many texels of the
    /// image's longer side it spans, clamped to the pyramid (0 = the image itself).
    [[nodiscard]] float level_of_detail(float uv_width) const;

    /// The colour over a footprint `uv_width` wide at uv (channels as sample_bilinear_color):
    /// bilinear in the two levels around level_of_detail, blended linearly between them.
    [[nodiscard]] Color sample_color(const Vec2& uv, float uv_width, WrapMode wrap) const;

private:
    std::shared_ptr<const Image> base_;
    std::vector<Image> coarser_;
};

}  // namespace glint
