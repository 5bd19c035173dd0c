#pragma once
/// \file Integrator base: owns the pixel loop; subclasses compute radiance along a ray.

#include "glint/image/film.h"
#include "glint/integrators/render_settings.h"
#include "glint/integrators/tile_grid.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/sampling/sampler.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace glint {

class RenderScene;

struct RenderStats {
    /// Every ray cast into the scene: camera, reflection, refraction and shadow rays.
    uint64_t rays = 0;
    double seconds = 0.0;
    /// Tiles finished (before and during this call), of how many; fewer when a stop was asked for.
    uint32_t tiles_done = 0;
    uint32_t tiles = 0;
    [[nodiscard]] bool complete() const { return tiles_done == tiles; }
};

/// Per-pixel-sample context handed to Li(): the sample generator and a ray counter.
struct TraceContext {
    Sampler& sampler;
    uint64_t rays = 0;
};

/// The threads this machine runs at once; more would not render faster.
[[nodiscard]] uint32_t max_render_threads();

class Integrator {
public:
    /// Called from worker threads as tiles finish: (finished tiles, total tiles).
    using ProgressCallback = std::function<void(uint32_t, uint32_t)>;

    virtual ~Integrator() = default;

    /// Add settings.samples_per_axis² samples per pixel of the prepared scene to `film`, in
    /// parallel 16×16 tiles, each weighted by settings.filter. The result does not depend on
    /// the thread count: every sample is a function of (seed, pixel, sample index). A
    /// thread count above max_render_threads() runs that many threads. Once `stop` is
    /// set (from a signal handler, say), tiles not yet begun are skipped and the tiles in
    /// flight finish: every pixel of the film then has all its samples or none. With
    /// `tiles`, tiles it marks done are skipped (a resumed render) and each finished tile is
    /// marked, so that what is finished can be saved (integrators/checkpoint.h).
    RenderStats render(const RenderScene& scene, const RenderSettings& settings, Film& film,
                       const ProgressCallback& progress = {}, const std::atomic<bool>* stop = nullptr,
                       TileGrid* tiles = nullptr) const;

    /// Radiance arriving at the camera along `ray`.
    [[nodiscard]] virtual Color Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const = 0;

    /// One line for each part of `scene` this integrator ignores (shown before rendering).
    [[nodiscard]] virtual std::vector<std::string> warnings(const RenderScene& scene) const {
        (void)scene;
        return {};
    }
};

}  // namespace glint
