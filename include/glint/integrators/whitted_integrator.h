#pragma once
/// \file Turner Whitted's recursive ray tracer (1980).

#include "glint/integrators/integrator.h"
#include "glint/integrators/ior_stack.h"

namespace glint {

struct Material;
struct SurfaceInteraction;

/// Direct light (ambient, Lambert, optional Blinn-Phong) with shadow rays, recursive
/// mirror reflection, and refraction with Schlick Fresnel and total internal reflection,
/// following the material equation in glint/materials/material.h.
class WhittedIntegrator final : public Integrator {
public:
    explicit WhittedIntegrator(uint32_t max_depth = 5) : max_depth_(max_depth) {}

    [[nodiscard]] Color Li(const Scene& scene, const Ray& ray, TraceContext& context) const override;

    /// Radiance along `ray` at recursion `depth` inside the media of `media`.
    [[nodiscard]] Color trace(const Scene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                              TraceContext& context) const;

private:
    [[nodiscard]] Color direct_light(const Scene& scene, const Material& m, const SurfaceInteraction& si,
                                     const Vec3& to_viewer, const Vec3& n, TraceContext& context) const;

    uint32_t max_depth_;
};

}  // namespace glint
