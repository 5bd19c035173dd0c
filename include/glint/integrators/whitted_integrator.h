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

/// Direct light (ambient, Lambert, optional Blinn-Phong) with shadow rays, recursive
/// mirror reflection, and refraction with Schlick Fresnel and total internal reflection,
/// following the material equation in docs/shading.md. Area lights are sampled
/// `light_samples` times at every shading point, the samples stratified among themselves,
/// so their penumbrae are smooth even at one sample per pixel.
class WhittedIntegrator final : public Integrator {
public:
    explicit WhittedIntegrator(uint32_t max_depth = 5, uint32_t light_samples = 1)
        : max_depth_(max_depth), light_samples_(light_samples < 1 ? 1 : light_samples) {}
    /// The registry's factory: max_depth and light_samples from the settings.
    [[nodiscard]] static std::unique_ptr<Integrator> create(const RenderSettings& settings);

    [[nodiscard]] Color Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const override;

    /// Radiance along `ray` at recursion `depth` inside the media of `media`.
    [[nodiscard]] Color trace(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                              TraceContext& context) const;

private:
    /// trace(), compiled twice: recording each ray into context.tree (context.branch says how
    /// the ray came about), or (the render) not, so that the render pays nothing for it.
    template <bool Record>
    [[nodiscard]] Color trace_ray(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                                  TraceContext& context) const;
    /// Radiance leaving the hit `si` on `object`, of material `m`, back along `ray`; when
    /// recording, context.node is the ray that hit.
    template <bool Record>
    [[nodiscard]] Color shade(const RenderScene& scene, const Ray& ray, uint32_t object, const SurfaceInteraction& si,
                              const Material& m, uint32_t depth, const IorStack& media, TraceContext& context) const;
    /// Σ over lights of the BSDF's smooth lobes times the visible light (f·L·cosθ/pdf).
    template <bool Record>
    [[nodiscard]] Color direct_light(const RenderScene& scene, const Bsdf& bsdf, const SurfaceInteraction& si,
                                     const Vec3& ng, TraceContext& context) const;

    uint32_t max_depth_;
    uint32_t light_samples_;
};

}  // namespace glint
