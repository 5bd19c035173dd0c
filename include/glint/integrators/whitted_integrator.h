#pragma once
/// \file Turner Whitted's recursive ray tracer (1980), with stratified area-light sampling.

#include "glint/integrators/integrator.h"
#include "glint/integrators/ior_stack.h"

#include <memory>

namespace glint {

class Bsdf;
struct Material;
struct Hit;
struct SurfaceInteraction;
struct ShadingPoint;
struct HitShading;

/// Direct light (ambient, Lambert, optional Blinn-Phong) with shadow rays, recursive
/// mirror reflection, and refraction with Schlick Fresnel and total internal reflection,
/// following the material equation in docs/shading.md. Area lights are sampled
/// `light_samples` times at every shading point, the samples stratified among themselves,
/// so their penumbrae are smooth even at one sample per pixel.
///
/// Rough surfaces (GGX lobes, roughness > 0) are traced with `glossy_samples` stratified
/// samples of their glossy lobes at the first rough surface of a ray tree, and one sample at
/// rough surfaces below it (splitting once, not at every level). Direct light reaches the
/// glossy lobes through light samples too; emission that glossy samples find on area lights
/// is weighed against those light samples by Veach's power heuristic with sample counts
/// (Veach 1997, §9.2.4), so that neither small highlights nor large lights are noisy.
class WhittedIntegrator final : public Integrator {
public:
    explicit WhittedIntegrator(uint32_t max_depth = 5, uint32_t light_samples = 1, uint32_t glossy_samples = 4)
        : max_depth_(max_depth),
          light_samples_(light_samples < 1 ? 1 : light_samples),
          glossy_samples_(glossy_samples < 1 ? 1 : glossy_samples) {}
    /// The registry's factory: max_depth, light_samples and glossy_samples from the settings.
    [[nodiscard]] static std::unique_ptr<Integrator> create(const RenderSettings& settings);

    [[nodiscard]] Color Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const override;
    /// Li() for a packet of camera rays from their first hits; the shadow rays from those
    /// hits toward each point, spot or directional light go as packets too, and so do their
    /// mirror reflections.
    void Li_given_first_hits(const RenderScene& scene, const FirstHits& first, std::span<TraceContext> contexts,
                             std::span<Color> radiance) const override;
    [[nodiscard]] bool takes_first_hits() const override { return true; }

    /// Radiance along `ray` at recursion `depth` inside the media of `media`.
    [[nodiscard]] Color trace(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                              TraceContext& context) const;

private:
    /// trace(), compiled twice: recording each ray into context.tree (context.branch says how
    /// the ray came about), or (the render) not, so that the render pays nothing for it.
    /// Takes the ray by value, which it traces in place: a caller builds it in the call.
    template <bool Record>
    [[nodiscard]] Color trace_ray(const RenderScene& scene, Ray ray, uint32_t depth, const IorStack& media,
                                  TraceContext& context) const;
    /// trace_ray() from the ray's closest hit (`hit`, null for a miss) on: the background, or
    /// the shaded hit; `node` is the ray's node in context.tree when recording.
    template <bool Record>
    [[nodiscard]] Color radiance_from_hit(const RenderScene& scene, const Ray& ray, const Hit* hit, uint32_t depth,
                                          const IorStack& media, int32_t node, TraceContext& context) const;
    /// shade_hit()'s start, `si` on `hit` of `ray`: the ray's cone there (the texture
    /// footprint), the hit in the tree when recording; returns what the radiance from the
    /// hit keeps on its way back along the ray (absorption inside a dielectric).
    template <bool Record>
    [[gnu::always_inline]] [[nodiscard]] inline Color begin_hit(const RenderScene& scene, const Ray& ray,
                                                                const Hit& hit, SurfaceInteraction& si,
                                                                const IorStack& media, int32_t node,
                                                                TraceContext& context) const;
    /// radiance_from_hit() for a hit, given its surface interaction `si` (which it completes:
    /// texture footprint, normal map). Inlined into radiance_from_hit(), which every ray
    /// runs: called there, it made scenes without meshes render 1 % slower. TracedAhead:
    /// the hit is a camera ray's first, whose shadow rays toward delta lights
    /// context.first_hit_shadows holds (shade() and direct_light() pass it on), and whose
    /// mirror ray context.first_hit_mirror may hold; compiled apart, so that other hits pay
    /// nothing for it.
    template <bool Record, bool TracedAhead = false>
    [[gnu::always_inline]] [[nodiscard]] inline Color shade_hit(const RenderScene& scene, const Ray& ray,
                                                                const Hit& hit, SurfaceInteraction& si, uint32_t depth,
                                                                const IorStack& media, int32_t node,
                                                                TraceContext& context) const;
    /// Radiance leaving the hit `si` on `object`, of material `m`, back along `ray`; when
    /// recording, context.node is the ray that hit.
    template <bool Record, bool TracedAhead = false>
    [[nodiscard]] Color shade(const RenderScene& scene, const Ray& ray, uint32_t object, const SurfaceInteraction& si,
                              const Material& m, uint32_t depth, const IorStack& media, TraceContext& context) const;
    /// shade() where `local` is the hit's shading, worked out already (shade() works it out
    /// and inlines this; Li_given_first_hits() works out a packet's before it traces their
    /// mirror rays).
    template <bool Record, bool TracedAhead = false>
    [[gnu::always_inline]] [[nodiscard]] inline Color shade_with(const RenderScene& scene, const Ray& ray,
                                                                 uint32_t object, const SurfaceInteraction& si,
                                                                 const Material& m, const HitShading& local,
                                                                 uint32_t depth, const IorStack& media,
                                                                 TraceContext& context) const;
    /// Σ over lights of the BSDF's smooth and glossy lobes times the visible light
    /// (f·L·|cosθ|/pdf); with `glossy_count` glossy samples to be traced from here, the glossy
    /// part of area lights' samples is MIS-weighted against them.
    template <bool Record, bool TracedAhead = false>
    [[nodiscard]] Color direct_light(const RenderScene& scene, const Bsdf& bsdf, const SurfaceInteraction& si,
                                     const Vec3& ng, uint32_t glossy_count, TraceContext& context) const;
    /// The glossy lobes' light: `count` stratified samples, each traced at depth + 1 with
    /// weight f·|cos|/pdf / count. Not inlined into shade(), which every hit runs: rough
    /// surfaces are the rarer case.
    template <bool Record>
    [[gnu::noinline]] [[nodiscard]] Color glossy(const RenderScene& scene, const Bsdf& bsdf,
                                                 const SurfaceInteraction& si, const ShadingPoint& sp, float ior,
                                                 uint32_t count, uint32_t depth, const IorStack& media,
                                                 TraceContext& context) const;
    /// `emission` found by the glossy sample that cast the ray being traced
    /// (context.glossy_origin) times its MIS weight, if it hit area light `object` at `si`.
    /// Out of line: inlined, the product could fuse (FMA) with the next sum in the render's
    /// instantiation of shade() but not in the recording one, which also records it, and
    /// glint explain would differ from glint render in the last bit.
    [[gnu::noinline]] [[nodiscard]] Color glossy_emission_weight(const RenderScene& scene, uint32_t object,
                                                                 const SurfaceInteraction& si,
                                                                 const TraceContext& context,
                                                                 const Color& emission) const;
    /// The background a glossy sample's ray escaped to, times its MIS weight against the
    /// environment light's samples when the scene lights with it. Out of line as above.
    [[gnu::noinline]] [[nodiscard]] Color glossy_background_weight(const RenderScene& scene, const Ray& ray,
                                                                   const TraceContext& context,
                                                                   const Color& background) const;

    uint32_t max_depth_;
    uint32_t light_samples_;
    uint32_t glossy_samples_;
};

}  // namespace glint
