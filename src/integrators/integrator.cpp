#include "glint/integrators/integrator.h"

#include "glint/scene/scene.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

constexpr uint32_t kTileSize = 16;

/// Map a uniform ξ in [0,1) to the tent distribution on (-1, 1) by inverting its CDF.
float sample_tent(float xi) {
    return xi < 0.5f ? std::sqrt(2.0f * xi) - 1.0f : 1.0f - std::sqrt(2.0f - 2.0f * xi);
}

}  // namespace

Color Integrator::render_pixel(const Scene& scene, const RenderSettings& settings, uint32_t x, uint32_t y,
                               uint64_t& rays) const {
    Rng rng(settings.seed, uint64_t(y) * settings.width + x);
    TraceContext context{rng};
    const uint32_t n = settings.samples_per_axis;
    Color sum;
    for (uint32_t sy = 0; sy < n; ++sy) {
        for (uint32_t sx = 0; sx < n; ++sx) {
            // Stratified jitter: one uniform sample in each of the N×N cells of the pixel.
            const float jx = (float(sx) + rng.uniform()) / float(n);
            const float jy = (float(sy) + rng.uniform()) / float(n);
            float fx, fy;
            if (settings.filter == PixelFilter::Tent) {
                fx = float(x) + 0.5f + sample_tent(jx);
                fy = float(y) + 0.5f + sample_tent(jy);
            } else {
                fx = float(x) + jx;
                fy = float(y) + jy;
            }
            const Ray ray = scene.camera.generate_ray(fx, fy, int(settings.width), int(settings.height));
            sum += Li(scene, ray, context);
        }
    }
    rays += context.rays;
    return sum / float(n * n);
}

RenderStats Integrator::render(const Scene& scene, const RenderSettings& settings, Film& film,
                               const ProgressCallback& progress) const {
    if (!scene.prepared()) throw std::logic_error("Scene::prepare() must be called before rendering");
    if (film.width() != settings.width || film.height() != settings.height)
        throw std::invalid_argument("film size differs from the render settings");
    if (settings.samples_per_axis == 0) throw std::invalid_argument("samples per axis must be at least 1");
    const auto start = std::chrono::steady_clock::now();
    const uint32_t tiles_x = (settings.width + kTileSize - 1) / kTileSize;
    const uint32_t tiles_y = (settings.height + kTileSize - 1) / kTileSize;
    const uint32_t tile_count = tiles_x * tiles_y;
    std::atomic<uint64_t> rays{0};
    std::atomic<uint32_t> finished{0};

    auto render_tiles = [&] {
        tbb::parallel_for(tbb::blocked_range<uint32_t>(0, tile_count, 1), [&](const tbb::blocked_range<uint32_t>& r) {
            for (uint32_t tile = r.begin(); tile != r.end(); ++tile) {
                const uint32_t x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
                const uint32_t x1 = std::min(x0 + kTileSize, settings.width);
                const uint32_t y1 = std::min(y0 + kTileSize, settings.height);
                uint64_t tile_rays = 0;
                for (uint32_t y = y0; y < y1; ++y)
                    for (uint32_t x = x0; x < x1; ++x) film.set(x, y, render_pixel(scene, settings, x, y, tile_rays));
                rays += tile_rays;
                const uint32_t done = ++finished;
                if (progress) progress(done, tile_count);
            }
        });
    };
    if (settings.threads == 0) {
        render_tiles();
    } else {
        tbb::task_arena arena(int(settings.threads));
        arena.execute(render_tiles);
    }
    RenderStats stats;
    stats.rays = rays.load();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace glint
