#pragma once
/// \file How to render: image size, samples, pixel filter, integrator and its parameters,
/// seed, threads. One plain description, filled by a scene file and overridden by the
/// command line; the film and the integrator are made from it.

#include "glint/image/aov.h"
#include "glint/integrators/adaptive_sampling.h"
#include "glint/integrators/pixel_rect.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// Reconstruction filter: how a pixel's samples are spread and weighted (image/filter.h).
enum class PixelFilter {
    /// Uniform over a square of half-width `radius` (0.5: the pixel), equal weights.
    Box,
    /// A tent of radius `radius` (default 1 pixel), sampled by its inverse CDF.
    Tent,
    /// A Gaussian with σ = radius/3, truncated at `radius` (default 1.5 pixels).
    Gaussian,
    /// Mitchell-Netravali (B = C = 1/3) of radius `radius` (default 2 pixels); its negative
    /// lobes sharpen edges, and their samples carry negative weights.
    Mitchell,
};

/// How next-event estimation and BSDF sampling are weighted against each other (Veach 1997).
enum class MisHeuristic { Balance, Power };

/// N for `spp` samples per pixel taken as N×N stratified samples; none unless `spp` is a
/// positive square (scene files and the command line both ask for N²).
[[nodiscard]] inline std::optional<uint32_t> samples_per_axis(uint32_t spp) {
    const auto n = static_cast<uint32_t>(std::lround(std::sqrt(double(spp))));
    if (spp == 0 || n * n != spp) return std::nullopt;
    return n;
}

/// The accepted range of each numeric setting: one set of limits for scene files and the
/// command line.
struct SettingLimits {
    /// Image side in pixels (a 16384² film with its output copy takes about 8 GB).
    static constexpr uint32_t kMaxImageSide = 16384;
    static constexpr uint32_t kMaxSpp = 4096;
    /// Whitted recursion is this deep at most: bounded so no accepted value overflows a
    /// worker thread's stack.
    static constexpr uint32_t kMaxDepth = 64;
    static constexpr uint32_t kMaxLightSamples = 1024;
    static constexpr uint32_t kMaxGlossySamples = 1024;
    static constexpr float kMaxFilterRadius = 16.0f;
    static constexpr uint32_t kMaxThreads = 1024;
};

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    /// N of the N×N stratified jittered samples per pixel.
    uint32_t samples_per_axis = 1;
    /// Maximum number of bounces after the camera ray (reflection, refraction, scattering).
    uint32_t max_depth = 5;
    uint64_t seed = 0;
    PixelFilter filter = PixelFilter::Box;
    /// Filter radius in pixels; 0 = the filter's default.
    float filter_radius = 0.0f;
    /// Integrator by registry name: "whitted" or "path" (integrators/integrator_registry.h).
    std::string integrator = "whitted";
    /// Whitted: samples per area light at every shading point (stratified among themselves).
    uint32_t light_samples = 1;
    /// Whitted: samples of the glossy lobes at the first rough surface a ray tree meets
    /// (stratified among themselves; one at the rough surfaces below it).
    uint32_t glossy_samples = 4;
    /// Path: the MIS weighting of light and BSDF samples.
    MisHeuristic mis = MisHeuristic::Power;
    /// 0 = all cores.
    uint32_t threads = 0;
    /// When set, pixels stop taking samples once their error is small enough; the N² above
    /// is then the most a pixel takes (a power of 4: integrators/adaptive_sampling.h).
    std::optional<AdaptiveSampling> adaptive;
    /// Outputs written beside the image as extra EXR channels, in this order, each once.
    std::vector<Aov> aovs;
    /// Render only this region (--crop): the tiles that overlap it, whole, so that each of its
    /// pixels is the one a full render gives (the samples of a pixel depend on nothing else,
    /// and adaptive sampling looks at neighbours within the tile).
    std::optional<PixelRect> crop;
};

}  // namespace glint
