#pragma once
/// \file A unidirectional path tracer with next-event estimation and multiple importance
/// sampling (Veach 1997, ch. 9; pbrt-v4's PathIntegrator).

#include "glint/integrators/integrator.h"

#include <memory>

namespace glint {

/// At every bounce: one light chosen uniformly and sampled (next-event estimation), and one
/// BSDF sample that continues the path; emission reached by a BSDF sample is weighted
/// against the light sample that could have found it by the balance or power heuristic.
/// Delta lobes (mirror, smooth glass) continue the path with full weight, and emission they
/// reach counts in full; glossy lobes (rough metal and glass) are smooth lobes like Lambert's,
/// lit by light samples from either side of the surface. Russian roulette ends paths after three bounces with
/// probability 1 − max(throughput), never above 0.95. Dielectrics block light like any surface (no shadow-ray
/// shortcut), and the Whitted-only ambient term is ignored.
class PathIntegrator final : public Integrator {
public:
    explicit PathIntegrator(uint32_t max_depth = 5, MisHeuristic heuristic = MisHeuristic::Power)
        : max_depth_(max_depth), heuristic_(heuristic) {}
    /// The registry's factory: max_depth and mis from the settings.
    [[nodiscard]] static std::unique_ptr<Integrator> create(const RenderSettings& settings);

    [[nodiscard]] Color Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const override;
    [[nodiscard]] std::vector<std::string> warnings(const RenderScene& scene) const override;

private:
    /// Weight of a sample drawn with density `pdf_a` against another strategy's `pdf_b`.
    [[nodiscard]] float mis_weight(float pdf_a, float pdf_b) const;

    uint32_t max_depth_;
    MisHeuristic heuristic_;
};

}  // namespace glint
