#pragma once
/// \file Integrator base: owns the pixel loop; subclasses compute radiance along a ray.

#include "glint/image/aov_film.h"
#include "glint/image/film.h"
#include "glint/integrators/ray_cone.h"
#include "glint/integrators/ray_tree.h"
#include "glint/integrators/render_settings.h"
#include "glint/integrators/tile_grid.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/sampling/sampler.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint {

class Camera;
class DeltaLightShadows;
class Filter;
class RenderScene;
struct Hit;
struct PacketHits;

struct RenderStats {
    /// Every ray cast into the scene: camera, reflection, refraction and shadow rays.
    uint64_t rays = 0;
    double seconds = 0.0;
    /// Tiles finished (before and during this call), of how many; fewer when a stop was asked for.
    uint32_t tiles_done = 0;
    uint32_t tiles = 0;
    [[nodiscard]] bool complete() const { return tiles_done == tiles; }
};

/// Where a glossy sample of the Whitted integrator left from, and with what density.
struct GlossyOrigin {
    Vec3 point;
    /// Solid-angle density of the sampled direction over the glossy lobes; 0: not a glossy sample.
    float pdf = 0.0f;
    /// Glossy samples taken at that point.
    uint32_t samples = 0;
    /// Its shading normal (the environment light's density depends on it).
    Vec3 normal;
};

/// A ray traced ahead of the shading that casts it, in a packet with its neighbours': the
/// ray (null: none) and its closest hit (null: it found nothing).
struct TracedRay {
    const Ray* ray = nullptr;
    const Hit* hit = nullptr;
};

/// Per-pixel-sample context handed to Li(): the sample generator, a ray counter and, when
/// a pixel is being explained, the tree its rays are recorded in.
struct TraceContext {
    Sampler& sampler;
    uint64_t rays = 0;
    RayTree* tree = nullptr;
    /// While recording: how the next ray comes about, and the ray being shaded. Kept here
    /// rather than passed down a recursive integrator's calls, whose arguments the render pays
    /// for at every bounce (4-7 % for Whitted when they were arguments).
    RayBranch branch = {};
    int32_t node = -1;
    /// Where the camera ray's first hit goes when AOVs are rendered (null otherwise): the
    /// integrator fills it at the camera ray's hit and leaves it alone for a miss.
    FirstHit* first_hit = nullptr;
    /// Whitted: the glossy sample that cast the ray being traced (density 0 for any other
    /// ray), so that emission it finds on an area light is weighed against sampling that
    /// light (MIS). Here for the reason `branch` is.
    GlossyOrigin glossy_origin = {};
    /// Whitted: true while tracing below a glossy sample, where glossy lobes take one sample
    /// instead of glossy_samples, so a ray tree branches N ways once rather than N^depth.
    bool below_glossy = false;
    /// The cone of the ray about to be traced (integrators/ray_cone.h): the camera ray's at
    /// first; an integrator moves it along each ray and bounces it at each hit, so texture
    /// lookups filter what a pixel sample covers. Here for the reason `branch` is.
    RayCone cone = {};
    /// Whitted: the shadow rays of the camera ray's first hit, already traced in packets with
    /// its neighbours' (null otherwise); read only while shading that hit. Here for the
    /// reason `branch` is.
    const DeltaLightShadows* first_hit_shadows = nullptr;
    /// Whitted: the mirror ray of the camera ray's first hit, already traced in a packet
    /// with its neighbours' (none otherwise); taken by shade() at that hit. Here for the
    /// reason `branch` is.
    TracedRay first_hit_mirror = {};
};

/// The camera rays of neighbouring pixels of a row after the render found their closest
/// hits as one packet (RenderScene::intersect_packet): what Li_given_first_hits() shades.
struct FirstHits {
    std::span<const Ray> rays;
    const PacketHits& hits;
    /// The lanes that hit.
    uint32_t hit_lanes;

    [[nodiscard]] bool hit(uint32_t lane) const { return (hit_lanes >> lane & 1) != 0; }
};

/// Sample `index` of pixel (x, y): one lane of a packet of camera samples.
struct PixelSample {
    uint32_t x = 0, y = 0, index = 0;
};

/// The threads this process may run at once: the machine's, or fewer while a
/// tbb::global_control bounds the process (`glint render --threads`); more would not render
/// faster.
[[nodiscard]] uint32_t max_render_threads();

class Integrator {
public:
    /// Called from worker threads as tiles finish: (finished tiles, total tiles).
    using ProgressCallback = std::function<void(uint32_t, uint32_t)>;

    virtual ~Integrator() = default;

    /// Add settings.samples_per_axis² samples per pixel of the prepared scene to `film`, in
    /// parallel 16×16 tiles, each weighted by settings.filter. The result does not depend on
    /// the thread count: every sample is a function of (seed, pixel, sample index). A
    /// thread count above max_render_threads() runs max_render_threads(). Once `stop` is
    /// set (from a signal handler, say), tiles not yet begun are skipped and the tiles in
    /// flight finish: every pixel of the film then has all its samples or none. With
    /// `tiles`, tiles it marks done are skipped (a resumed render) and each finished tile is
    /// marked, so that what is finished can be saved (integrators/checkpoint.h). With
    /// `aovs`, every sample's first hit and radiance also go there.
    RenderStats render(const RenderScene& scene, const RenderSettings& settings, Film& film,
                       const ProgressCallback& progress = {}, const std::atomic<bool>* stop = nullptr,
                       TileGrid* tiles = nullptr, AovFilm* aovs = nullptr) const;

    /// Render exactly the tiles `tiles` of TileGrid(film.width(), film.height()), whole: the
    /// unit of work of a distributed render. Their pixels are the ones render() gives them.
    RenderStats render_tiles(const RenderScene& scene, const RenderSettings& settings, Film& film,
                             std::span<const uint32_t> tiles, AovFilm* aovs = nullptr) const;

    /// Pixel (x, y) of the image `render` makes with these settings: every sample as the
    /// render takes it, and the rays of sample `sample` (of every sample when none is
    /// given) recorded. Throws std::out_of_range for a pixel or sample that does not exist.
    /// `camera` replaces the scene's (the viewer's orbit camera) when given.
    [[nodiscard]] PixelExplanation explain(const RenderScene& scene, const RenderSettings& settings, uint32_t x,
                                           uint32_t y, std::optional<uint32_t> sample = std::nullopt,
                                           const Camera* camera = nullptr) const;

    /// The rays of sample `index` of pixel (x, y) seen through `camera`, as explain() records
    /// them (the viewer's heatmaps retrace them).
    [[nodiscard]] RayTree record_sample(const RenderScene& scene, const RenderSettings& settings, const Camera& camera,
                                        uint32_t x, uint32_t y, uint32_t index) const;

    /// One pass of a progressive render (the viewer's): sample `index` of the settings' N×N
    /// for every pixel of `film`, seen through `camera`. Passes 0, 1, ..., N²−1 in order
    /// with the scene's camera make the film render() makes, bit for bit: each pixel gets
    /// the same samples in the same order. Stops between tiles once *stop is set
    /// (stats.complete() is then false and the film holds part of a pass).
    RenderStats render_pass(const RenderScene& scene, const Camera& camera, const RenderSettings& settings, Film& film,
                            uint32_t index, const std::atomic<bool>* stop = nullptr) const;

    /// Radiance arriving at the camera along `ray`.
    [[nodiscard]] virtual Color Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const = 0;

    /// Li() for each camera ray of a packet whose closest hits the render has already found:
    /// lane k, traced with contexts[k] (its pixel's sampler, cone and first-hit record), gets
    /// in radiance[k] what Li() gives it. An integrator that overrides it says so with
    /// takes_first_hits(), and may trace more of the lanes' rays as packets. The default
    /// calls Li() lane by lane.
    virtual void Li_given_first_hits(const RenderScene& scene, const FirstHits& first, std::span<TraceContext> contexts,
                                     std::span<Color> radiance) const;
    /// Whether the render should trace camera rays in packets for Li_given_first_hits().
    [[nodiscard]] virtual bool takes_first_hits() const { return false; }

    /// One line for each part of `scene` this integrator ignores (shown before rendering).
    [[nodiscard]] virtual std::vector<std::string> warnings(const RenderScene& scene) const {
        (void)scene;
        return {};
    }

private:
    /// Render the tiles `order` of `grid` (skipping those it marks done) into `film`; what
    /// render() and render_tiles() share.
    RenderStats render_listed_tiles(const RenderScene& scene, const RenderSettings& settings, Film& film,
                                    TileGrid& grid, std::span<const uint32_t> order, const ProgressCallback& progress,
                                    const std::atomic<bool>* stop, AovFilm* aovs) const;
    /// With adaptive sampling, the samples pixel (x, y) takes at least, from its tile's first
    /// batches (explain() follows the render's decisions).
    [[nodiscard]] uint32_t adaptive_minimum(const RenderScene& scene, const Camera& camera, const Filter& filter,
                                            const RenderSettings& settings, uint32_t x, uint32_t y) const;
    /// Sample `index` of pixel (x, y) of a `width`×`height` image: where it falls, its
    /// filter weight and its radiance. The one place both render and explain take samples.
    CameraSample take_sample(const RenderScene& scene, const Camera& camera, const Filter& filter, uint32_t x,
                             uint32_t y, uint32_t index, uint32_t width, uint32_t height, TraceContext& context) const;
    /// take_sample() up to its camera ray: fills `sample`'s position and filter weight and
    /// context.cone, and leaves the sampler where Li() takes over.
    Ray camera_ray(const RenderScene& scene, const Camera& camera, const Filter& filter, uint32_t x, uint32_t y,
                   uint32_t index, uint32_t width, uint32_t height, TraceContext& context, CameraSample& sample) const;
    /// The point of the camera's lens and the time a camera ray takes.
    struct LensAndTime {
        Vec2 u_lens;
        float time = 0.0f;
    };
    /// camera_ray() up to the ray itself: draws `sample`'s position and filter weight, then
    /// the lens point and time where the scene needs them (Camera::generate_ray's arguments).
    /// Inlined into the packet loop (integrator.cpp, the only file that calls it): called,
    /// it cost the dragon scene without its objects 4 % more CPU.
    [[gnu::always_inline]] inline LensAndTime start_camera_sample(const RenderScene& scene, const Camera& camera,
                                                                  const Filter& filter, uint32_t x, uint32_t y,
                                                                  uint32_t index, uint32_t width, Sampler& sampler,
                                                                  CameraSample& sample) const;
    /// take_sample() for each of `lanes` (at most RayPacket::kSize), their camera rays traced
    /// as one packet; lane k draws from `samplers[k]`. Each sample, with its radiance and
    /// (with `aovs`) its camera ray's first hit, goes to `add(x, y, sample, first_hit)`, in
    /// the order of the lanes.
    template <class AddSample>
    void take_packet_samples(const RenderScene& scene, const Filter& filter, std::span<const PixelSample> lanes,
                             uint32_t width, uint32_t height, std::span<Sampler> samplers, bool aovs, uint64_t& rays,
                             const AddSample& add) const;
};

}  // namespace glint
