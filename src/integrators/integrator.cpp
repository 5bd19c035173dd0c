#include "glint/integrators/integrator.h"

#include "glint/image/filter.h"
#include "glint/scene/render_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>

namespace glint {

uint32_t max_render_threads() { return static_cast<uint32_t>(tbb::info::default_concurrency()); }

RenderStats Integrator::render(const RenderScene& scene, const RenderSettings& settings, Film& film,
                               const ProgressCallback& progress, const std::atomic<bool>* stop, TileGrid* tiles) const {
    if (settings.samples_per_axis == 0) throw std::invalid_argument("samples per axis must be at least 1");
    const Filter filter(settings.filter, settings.filter_radius);
    const auto start = std::chrono::steady_clock::now();
    const uint32_t width = film.width(), height = film.height();
    TileGrid own_tiles(width, height);
    TileGrid& grid = tiles ? *tiles : own_tiles;
    if (grid.width() != width || grid.height() != height) throw std::invalid_argument("tile grid and film differ in size");
    const uint32_t tile_count = grid.count();
    const uint32_t n = settings.samples_per_axis;
    std::atomic<uint64_t> rays{0};
    std::atomic<uint32_t> finished{grid.done_count()};

    auto render_tile = [&](uint32_t tile) {
        if (grid.done(tile) || (stop && stop->load(std::memory_order_relaxed))) return;
        const auto [x0, y0, x1, y1] = grid.bounds(tile);
        Sampler sampler(settings.seed, n);
        TraceContext context{sampler};
        for (uint32_t y = y0; y < y1; ++y)
            for (uint32_t x = x0; x < x1; ++x)
                for (uint32_t index = 0; index < n * n; ++index) {
                    sampler.start_pixel_sample(uint64_t(y) * width + x, index);
                    const FilterSample fs = filter.sample(sampler.pixel_2d());
                    const float fx = (float(x) + 0.5f) + fs.offset.x;
                    const float fy = (float(y) + 0.5f) + fs.offset.y;
                    const Ray ray = scene.camera().generate_ray(fx, fy, int(width), int(height));
                    film.add_sample(x, y, Li(scene, ray, context), fs.weight);
                }
        rays += context.rays;
        grid.mark_done(tile);
        const uint32_t done = ++finished;
        if (progress) progress(done, tile_count);
    };
    auto render_tiles = [&] {
        tbb::parallel_for(tbb::blocked_range<uint32_t>(0, tile_count, 1), [&](const tbb::blocked_range<uint32_t>& r) {
            for (uint32_t tile = r.begin(); tile != r.end(); ++tile) render_tile(tile);
        });
    };
    if (settings.threads == 0) {
        render_tiles();
    } else {
        tbb::task_arena arena(int(std::min(settings.threads, max_render_threads())));
        arena.execute(render_tiles);
    }
    RenderStats stats;
    stats.rays = rays.load();
    stats.tiles_done = finished.load();
    stats.tiles = tile_count;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace glint
