#pragma once
/// \file How to render: image size, samples, recursion depth, seed, threads.

#include <cstdint>

namespace glint {

/// Reconstruction filter: how a pixel's samples are spread over the image plane.
enum class PixelFilter {
    /// Samples uniform over the pixel's square, equally weighted.
    Box,
    /// Samples distributed by a tent of radius one pixel around the pixel centre (filter
    /// importance sampling), equally weighted: softer edges than the box, no negative lobes.
    Tent,
};

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    /// N of the N×N stratified jittered samples per pixel.
    uint32_t samples_per_axis = 1;
    /// Maximum number of reflection/refraction bounces after the camera ray.
    uint32_t max_depth = 5;
    uint64_t seed = 0;
    PixelFilter filter = PixelFilter::Box;
    /// 0 = all cores.
    uint32_t threads = 0;
};

}  // namespace glint
