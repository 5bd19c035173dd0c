#include "glint/integrators/integrator.h"

#include "glint/accel/ray_packet.h"
#include "glint/image/filter.h"
#include "glint/scene/render_scene.h"
#include "tile_sampling.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace glint {

uint32_t max_render_threads() {
    return uint32_t(
        std::min<std::size_t>(tbb::info::default_concurrency(),
                              tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
}

namespace {

/// `render_tile(t)` for every tile t < count, in parallel on `threads` threads (0: all).
template <class F>
void for_each_tile(uint32_t threads, uint32_t count, const F& render_tile) {
    auto render_tiles = [&] {
        tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 1), [&](const tbb::blocked_range<uint32_t>& r) {
            for (uint32_t tile = r.begin(); tile != r.end(); ++tile) render_tile(tile);
        });
    };
    if (threads == 0) {
        render_tiles();
    } else {
        tbb::task_arena arena(int(std::min(threads, max_render_threads())));
        arena.execute(render_tiles);
    }
}

/// Adaptive sampling needs a power-of-4 maximum (its sample order) and a batch within it.
void check_adaptive(const RenderSettings& settings) {
    if (!settings.adaptive) return;
    const uint32_t spp = settings.samples_per_axis * settings.samples_per_axis;
    if (!is_power_of_four(spp))
        throw std::invalid_argument("adaptive sampling needs a power of 4 samples per pixel at most (4, 16, 64, ...)");
    if (settings.adaptive->min_spp == 0 || settings.adaptive->min_spp > spp)
        throw std::invalid_argument("adaptive sampling: the minimum samples per pixel must be from 1 to the maximum");
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Integrator::LensAndTime Integrator::start_camera_sample(const RenderScene& scene, const Camera& camera,
                                                        const Filter& filter, uint32_t x, uint32_t y, uint32_t index,
                                                        uint32_t width, Sampler& sampler, CameraSample& sample) const {
    sampler.start_pixel_sample(uint64_t(y) * width + x, index);
    const FilterSample fs = filter.sample(sampler.pixel_2d());
    sample.film_position = Vec2((float(x) + 0.5f) + fs.offset.x, (float(y) + 0.5f) + fs.offset.y);
    sample.filter_weight = fs.weight;
    LensAndTime lt;
    // The lens takes a sampler dimension only when there is a lens, so that a pinhole
    // camera's images stay what they were.
    if (!camera.lens().is_pinhole()) lt.u_lens = sampler.next_2d();
    // Likewise time, only when something moves (motion blur): a static scene's images do
    // not depend on the shutter.
    lt.time = scene.has_motion() ? camera.time(sampler.next_1d()) : camera.shutter().open;
    return lt;
}

Ray Integrator::camera_ray(const RenderScene& scene, const Camera& camera, const Filter& filter, uint32_t x, uint32_t y,
                           uint32_t index, uint32_t width, uint32_t height, TraceContext& context,
                           CameraSample& sample) const {
    const LensAndTime lt = start_camera_sample(scene, camera, filter, x, y, index, width, context.sampler, sample);
    const Ray ray = camera.generate_ray(sample.film_position.x, sample.film_position.y, int(width), int(height),
                                        lt.u_lens, lt.time);
    context.cone = camera_ray_cone(camera, height, context.sampler.samples_per_axis());
    return ray;
}

CameraSample Integrator::take_sample(const RenderScene& scene, const Camera& camera, const Filter& filter, uint32_t x,
                                     uint32_t y, uint32_t index, uint32_t width, uint32_t height,
                                     TraceContext& context) const {
    CameraSample sample;
    const Ray ray = camera_ray(scene, camera, filter, x, y, index, width, height, context, sample);
    sample.radiance = Li(scene, ray, context);
    return sample;
}

template <class AddSample>
void Integrator::take_packet_samples(const RenderScene& scene, const Filter& filter, std::span<const PixelSample> lanes,
                                     uint32_t width, uint32_t height, std::span<Sampler> samplers, bool aovs,
                                     uint64_t& rays, const AddSample& add) const {
    const auto count = uint32_t(lanes.size());
    // Each lane's context: its own sampler and, for the AOVs, its own first-hit record.
    std::array<FirstHit, RayPacket::kSize> first_hits;
    auto context_of = [&](uint32_t k) {
        return TraceContext{.sampler = samplers[k], .first_hit = aovs ? &first_hits[k] : nullptr};
    };
    std::array<TraceContext, RayPacket::kSize> contexts = per_lane(context_of);
    // The lanes' samples first, then their camera rays all at once (Camera::generate_rays).
    const Camera& camera = scene.camera();
    std::array<CameraSample, RayPacket::kSize> samples;
    std::array<Vec2, RayPacket::kSize> film, u_lens;
    std::array<float, RayPacket::kSize> times;
    for (uint32_t k = 0; k < count; ++k) {
        const PixelSample& lane = lanes[k];
        const LensAndTime lt =
            start_camera_sample(scene, camera, filter, lane.x, lane.y, lane.index, width, samplers[k], samples[k]);
        film[k] = samples[k].film_position;
        u_lens[k] = lt.u_lens;
        times[k] = lt.time;
    }
    std::array<Ray, RayPacket::kSize> camera_rays;
    camera.generate_rays(std::span(film.data(), count), int(width), int(height), std::span(u_lens.data(), count),
                         std::span(times.data(), count), std::span(camera_rays.data(), count));
    // The lanes' samplers are copies of the render's one, with its samples per axis.
    const RayCone cone = camera_ray_cone(camera, height, samplers[0].samples_per_axis());
    for (uint32_t k = 0; k < count; ++k) contexts[k].cone = cone;
    RayPacket packet;
    for (uint32_t k = 0; k < count; ++k) packet.set(k, camera_rays[k]);
    PacketHits hits;
    const uint32_t hit_lanes = scene.intersect_packet(packet, hits);
    std::array<Color, RayPacket::kSize> radiance;
    Li_given_first_hits(scene, FirstHits{std::span(camera_rays.data(), count), hits, hit_lanes},
                        std::span(contexts.data(), count), radiance);
    for (uint32_t k = 0; k < count; ++k) {
        samples[k].radiance = radiance[k];
        rays += contexts[k].rays;
        add(lanes[k].x, lanes[k].y, samples[k], first_hits[k]);
    }
}

void Integrator::Li_given_first_hits(const RenderScene& scene, const FirstHits& first, std::span<TraceContext> contexts,
                                     std::span<Color> radiance) const {
    for (uint32_t k = 0; k < first.rays.size(); ++k) radiance[k] = Li(scene, first.rays[k], contexts[k]);
}

PixelExplanation Integrator::explain(const RenderScene& scene, const RenderSettings& settings, uint32_t x, uint32_t y,
                                     std::optional<uint32_t> sample, const Camera* camera) const {
    const uint32_t n = settings.samples_per_axis;
    if (n == 0) throw std::invalid_argument("samples per axis must be at least 1");
    if (x >= settings.width || y >= settings.height)
        throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                std::to_string(settings.width) + "×" + std::to_string(settings.height) + " image");
    if (sample && *sample >= n * n)
        throw std::out_of_range("sample " + std::to_string(*sample) + " does not exist: a pixel has " +
                                std::to_string(n * n) + " samples, 0 to " + std::to_string(n * n - 1));
    check_adaptive(settings);
    const Filter filter(settings.filter, settings.filter_radius);
    Sampler sampler(settings.seed, n);
    PixelExplanation explanation{.x = x, .y = y, .samples = {}, .value = {}};
    // A film of one pixel accumulates exactly as the render's film does at (x, y), and an
    // adaptive pixel stops where the render's does.
    Film pixel(1, 1);
    PixelError error;
    const uint32_t minimum =
        settings.adaptive ? adaptive_minimum(scene, camera ? *camera : scene.camera(), filter, settings, x, y) : 0;
    for (uint32_t k = 0; k < n * n; ++k) {
        if (settings.adaptive && converged(*settings.adaptive, error, minimum)) break;
        const uint32_t index = settings.adaptive ? progressive_cell(k, n) : k;
        RayTree tree;
        const bool recorded = !sample || *sample == k;
        TraceContext context{.sampler = sampler, .rays = 0, .tree = recorded ? &tree : nullptr};
        ExplainedSample s;
        static_cast<CameraSample&>(s) = take_sample(scene, camera ? *camera : scene.camera(), filter, x, y, index,
                                                    settings.width, settings.height, context);
        error.add(s.radiance.luminance());
        s.index = k;
        if (recorded) s.tree = std::move(tree);
        pixel.add_sample(0, 0, s.radiance, s.filter_weight);
        explanation.samples.push_back(std::move(s));
    }
    explanation.value = pixel.at(0, 0);
    return explanation;
}

uint32_t Integrator::adaptive_minimum(const RenderScene& scene, const Camera& camera, const Filter& filter,
                                      const RenderSettings& settings, uint32_t x, uint32_t y) const {
    // The first batches of the pixel's tile, as the render takes them.
    const uint32_t n = settings.samples_per_axis;
    const TileGrid grid(settings.width, settings.height);
    const TileGrid::Bounds b = grid.bounds(grid.tile_of(x, y));
    Sampler sampler(settings.seed, n);
    TraceContext context{sampler};
    const std::vector<PixelError> errors = tile_sampling::first_batches(
        b, *settings.adaptive, n, 1, [&](std::span<const PixelSample> lanes, const auto& then) {
            for (const PixelSample& s : lanes)
                then(s.x, s.y,
                     take_sample(scene, camera, filter, s.x, s.y, s.index, settings.width, settings.height, context)
                         .radiance);
        });
    return tile_sampling::tile_minimum_samples(b, errors, *settings.adaptive, n * n, x, y);
}

RayTree Integrator::record_sample(const RenderScene& scene, const RenderSettings& settings, const Camera& camera,
                                  uint32_t x, uint32_t y, uint32_t index) const {
    const Filter filter(settings.filter, settings.filter_radius);
    Sampler sampler(settings.seed, settings.samples_per_axis);
    RayTree tree;
    TraceContext context{.sampler = sampler, .rays = 0, .tree = &tree};
    (void)take_sample(scene, camera, filter, x, y, index, settings.width, settings.height, context);
    return tree;
}

RenderStats Integrator::render(const RenderScene& scene, const RenderSettings& settings, Film& film,
                               const ProgressCallback& progress, const std::atomic<bool>* stop, TileGrid* tiles,
                               AovFilm* aovs) const {
    TileGrid own_tiles(film.width(), film.height());
    TileGrid& grid = tiles ? *tiles : own_tiles;
    if (grid.width() != film.width() || grid.height() != film.height())
        throw std::invalid_argument("tile grid and film differ in size");
    return render_listed_tiles(scene, settings, film, grid, grid.tiles_overlapping(settings.crop), progress, stop,
                               aovs);
}

RenderStats Integrator::render_tiles(const RenderScene& scene, const RenderSettings& settings, Film& film,
                                     std::span<const uint32_t> tiles, AovFilm* aovs) const {
    TileGrid grid(film.width(), film.height());
    for (const uint32_t t : tiles)
        if (t >= grid.count()) throw std::out_of_range("render_tiles: a tile past the image");
    return render_listed_tiles(scene, settings, film, grid, tiles, {}, nullptr, aovs);
}

RenderStats Integrator::render_listed_tiles(const RenderScene& scene, const RenderSettings& settings, Film& film,
                                            TileGrid& grid, std::span<const uint32_t> order,
                                            const ProgressCallback& progress, const std::atomic<bool>* stop,
                                            AovFilm* aovs) const {
    if (settings.samples_per_axis == 0) throw std::invalid_argument("samples per axis must be at least 1");
    check_adaptive(settings);
    const Filter filter(settings.filter, settings.filter_radius);
    const auto start = std::chrono::steady_clock::now();
    const uint32_t width = film.width(), height = film.height();
    const auto already_done =
        uint32_t(std::count_if(order.begin(), order.end(), [&](uint32_t t) { return grid.done(t); }));
    const auto tile_count = uint32_t(order.size());
    const uint32_t n = settings.samples_per_axis;
    std::atomic<uint64_t> rays{0};
    std::atomic<uint32_t> finished{already_done};

    auto render_tile = [&](uint32_t tile) {
        if (grid.done(tile) || (stop && stop->load(std::memory_order_relaxed))) return;
        Sampler sampler(settings.seed, n);
        TraceContext context{sampler};
        FirstHit first_hit;
        if (aovs) context.first_hit = &first_hit;
        // Camera rays in packets of neighbouring pixels when the integrator shades first hits.
        const bool packets = takes_first_hits();
        const uint32_t group = packets ? RayPacket::kSize : 1;
        std::vector<Sampler> samplers(packets ? RayPacket::kSize : 0, sampler);
        // The samples `lanes`, each into the film (and the AOVs) and to `then`: as one packet,
        // or one by one. Each pixel takes its samples in order either way, each from the
        // sampler started for it, so the film is the same.
        auto take = [&](std::span<const PixelSample> lanes, const auto& then) {
            auto add = [&](uint32_t x, uint32_t y, const CameraSample& sample, const FirstHit& hit) {
                film.add_sample(x, y, sample.radiance, sample.filter_weight);
                if (aovs) aovs->add_sample(x, y, hit, sample.radiance);
                then(x, y, sample.radiance);
            };
            if (packets) {
                take_packet_samples(scene, filter, lanes, width, height, samplers, aovs != nullptr, context.rays, add);
                return;
            }
            for (const PixelSample& s : lanes) {
                first_hit.hit = false;
                add(s.x, s.y, take_sample(scene, scene.camera(), filter, s.x, s.y, s.index, width, height, context),
                    first_hit);
            }
        };
        if (settings.adaptive)
            tile_sampling::sample_adaptively(grid.bounds(tile), *settings.adaptive, n, group, take);
        else
            tile_sampling::sample_uniformly(grid.bounds(tile), n, group, take);
        rays += context.rays;
        grid.mark_done(tile);
        const uint32_t done = ++finished;
        if (progress) progress(done, tile_count);
    };
    for_each_tile(settings.threads, tile_count, [&](uint32_t i) { render_tile(order[i]); });
    RenderStats stats;
    stats.rays = rays.load();
    stats.tiles_done = finished.load();
    stats.tiles = tile_count;
    stats.seconds = seconds_since(start);
    return stats;
}

RenderStats Integrator::render_pass(const RenderScene& scene, const Camera& camera, const RenderSettings& settings,
                                    Film& film, uint32_t index, const std::atomic<bool>* stop) const {
    const uint32_t n = settings.samples_per_axis;
    if (n == 0) throw std::invalid_argument("samples per axis must be at least 1");
    if (index >= n * n) throw std::out_of_range("render_pass: sample index past the pixel's samples");
    const Filter filter(settings.filter, settings.filter_radius);
    const auto start = std::chrono::steady_clock::now();
    const uint32_t width = film.width(), height = film.height();
    const TileGrid grid(width, height);
    std::atomic<uint64_t> rays{0};
    std::atomic<uint32_t> finished{0};
    for_each_tile(settings.threads, grid.count(), [&](uint32_t tile) {
        if (stop && stop->load(std::memory_order_relaxed)) return;
        const auto [x0, y0, x1, y1] = grid.bounds(tile);
        Sampler sampler(settings.seed, n);
        TraceContext context{sampler};
        for (uint32_t y = y0; y < y1; ++y)
            for (uint32_t x = x0; x < x1; ++x) {
                const CameraSample sample = take_sample(scene, camera, filter, x, y, index, width, height, context);
                film.add_sample(x, y, sample.radiance, sample.filter_weight);
            }
        rays += context.rays;
        ++finished;
    });
    RenderStats stats;
    stats.rays = rays.load();
    stats.tiles_done = finished.load();
    stats.tiles = grid.count();
    stats.seconds = seconds_since(start);
    return stats;
}

}  // namespace glint
