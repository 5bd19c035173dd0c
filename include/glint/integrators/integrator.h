#pragma once
/// \file Integrator base: owns the pixel loop; subclasses compute radiance along a ray.

#include "glint/image/film.h"
#include "glint/integrators/render_settings.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/math/rng.h"

#include <cstdint>
#include <functional>

namespace glint {

class Scene;

struct RenderStats {
    /// Every ray cast into the scene: camera, reflection, refraction and shadow rays.
    uint64_t rays = 0;
    double seconds = 0.0;
};

/// Per-thread context handed to Li(): the pixel's random stream and a ray counter.
struct TraceContext {
    Rng& rng;
    uint64_t rays = 0;
};

class Integrator {
public:
    /// Called from worker threads as tiles finish: (finished tiles, total tiles).
    using ProgressCallback = std::function<void(uint32_t, uint32_t)>;

    virtual ~Integrator() = default;

    /// Render the prepared scene into `film` (sized settings.width × settings.height), in
    /// parallel 16×16 tiles. The result does not depend on the thread count: every pixel
    /// draws from its own random stream (seed, pixel index).
    RenderStats render(const Scene& scene, const RenderSettings& settings, Film& film,
                       const ProgressCallback& progress = {}) const;

    /// Radiance arriving at the camera along `ray`.
    [[nodiscard]] virtual Color Li(const Scene& scene, const Ray& ray, TraceContext& context) const = 0;

private:
    [[nodiscard]] Color render_pixel(const Scene& scene, const RenderSettings& settings, uint32_t x, uint32_t y,
                                     uint64_t& rays) const;
};

}  // namespace glint
