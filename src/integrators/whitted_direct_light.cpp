/// \file The Whitted integrator's direct light: Σ over lights of f·L·|cosθ|/pdf with shadow
/// rays (WhittedIntegrator::direct_light), apart from the rest of its shading so that each file
/// holds one part of the integrator.

#include "glint/integrators/delta_light_shadows.h"
#include "glint/integrators/shading_point.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"
#include "whitted_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace glint {

using whitted::power_heuristic;
using whitted::stratified_set;

template <bool Record, bool TracedAhead>
Color WhittedIntegrator::direct_light(const RenderScene& scene, const Bsdf& bsdf, const SurfaceInteraction& si,
                                      const Vec3& ng, uint32_t glossy_count, TraceContext& context) const {
    // Explain records the shadow rays it traces itself; only the render knows some already.
    static_assert(!(Record && TracedAhead));
    const int32_t node = context.node;
    Color sum;
    // Not when the light gives nothing, or where it is behind the surface (or a glass has no
    // smooth lobe toward it).
    auto casts_shadow_ray = [&](const LightSample& ls) {
        return ls.pdf > 0.0f && !ls.radiance.is_black() && bsdf.may_reflect(ls.direction);
    };
    // `answer`: the shadow ray's, when a packet has traced it with others. Inlined at its
    // three calls: left to GCC it was called, which cost spheres.toml 2.5 %.
    auto add = [&](const LightSample& ls, float weight, uint32_t light, std::optional<bool> answer = std::nullopt)
        __attribute__((always_inline)) {
        if (!casts_shadow_ray(ls)) return;
        ++context.rays;
        // Light from under the surface reaches only a rough dielectric's transmission, and it
        // comes through the material's own volume: the shadow ray starts on that side and glass
        // blocks it whatever dielectric_shadows says (the glossy samples bring the light that
        // finds its way through the glass; docs/shading.md).
        const bool through = dot(ls.direction, ng) < 0.0f;
        // Built where it is traced or recorded: a known answer needs no ray.
        auto shadow = [&] { return shadow_ray(si.p, through ? -ng : ng, ls, si.time); };
        std::optional<bool> known = answer;
        if constexpr (TracedAhead)
            if (!known && !through) known = context.first_hit_shadows->occluded(light);
        const bool blocked = known     ? *known
                             : through ? scene.occluded(shadow(), DielectricShadows::Opaque)
                                       : scene.occluded(shadow());
        if (blocked) {
            if constexpr (Record) context.tree->add_shadow_ray(node, shadow(), light, true, Color());
            return;
        }
        Color f;
        if (glossy_count > 0 && !ls.is_delta) {
            // The glossy samples traced from here can find this light too: the glossy part of f
            // takes the light sample's MIS weight, their emission the rest.
            const Bsdf::EvalParts parts = bsdf.eval_parts(ls.direction);
            const float w =
                power_heuristic(float(light_samples_) * ls.pdf, float(glossy_count) * bsdf.glossy_pdf(ls.direction));
            f = parts.all - parts.glossy * (1.0f - w);
        } else {
            f = bsdf.eval(ls.direction);
        }
        const Color c = f * ls.radiance * (std::abs(dot(bsdf.normal(), ls.direction)) * weight / ls.pdf);
        // The tree records what the sum gained, not c: recording c would give its product a
        // second use, and GCC then no longer fuses it into the sum (FMA) as it does in the
        // render's instantiation, so explain differed from render in the last bit.
        [[maybe_unused]] const Color before = sum;
        sum += c;
        if constexpr (Record) context.tree->add_shadow_ray(node, shadow(), light, false, sum - before);
    };
    const std::vector<const Light*>& lights = scene.all_lights();
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const Light* light = lights[i];
        if (light == scene.environment_light() && !scene.environment_lighting()) continue;
        if (light->is_delta()) {
            add(light->sample(si.p, Vec2()), 1.0f, i);
            continue;
        }
        // N stratified samples of this light: the estimate (1/N) Σ f·L·cosθ/pdf.
        std::array<Vec2, 16> small;
        std::vector<Vec2> large;
        const std::span<Vec2> us = stratified_set(context.sampler, light_samples_, small, large);
        const float weight = 1.0f / float(light_samples_);
        if (!Record && us.size() > 1) {
            // The samples' shadow rays leave one point toward one light: they share their
            // way through the scene, and trace faster as packets of eight (explain traces
            // and records them one by one; the answers are the same).
            for (std::size_t first = 0; first < us.size(); first += RayPacket::kSize) {
                const auto n = uint32_t(std::min<std::size_t>(RayPacket::kSize, us.size() - first));
                const auto ls = per_lane([&](uint32_t k) {
                    return k < n ? light->sample_at_surface(si.p, bsdf.normal(), us[first + k]) : LightSample{};
                });
                RayPacket packet;
                for (uint32_t k = 0; k < n; ++k)  // those from under the surface go alone (add())
                    if (casts_shadow_ray(ls[k]) && dot(ls[k].direction, ng) >= 0.0f)
                        packet.set(k, shadow_ray(si.p, ng, ls[k], si.time));
                const uint32_t blocked = packet.active ? scene.occluded_packet(packet) : 0;
                for (uint32_t k = 0; k < n; ++k)
                    add(ls[k], weight, i,
                        (packet.active >> k & 1) ? std::optional((blocked >> k & 1) != 0) : std::nullopt);
            }
            continue;
        }
        for (const Vec2& u : us) add(light->sample_at_surface(si.p, bsdf.normal(), u), weight, i);
    }
    return sum;
}

// The three that shade() calls: the render's, explain's (recording) and the render's first hits.
template Color WhittedIntegrator::direct_light<false, false>(const RenderScene&, const Bsdf&, const SurfaceInteraction&,
                                                             const Vec3&, uint32_t, TraceContext&) const;
template Color WhittedIntegrator::direct_light<true, false>(const RenderScene&, const Bsdf&, const SurfaceInteraction&,
                                                            const Vec3&, uint32_t, TraceContext&) const;
template Color WhittedIntegrator::direct_light<false, true>(const RenderScene&, const Bsdf&, const SurfaceInteraction&,
                                                            const Vec3&, uint32_t, TraceContext&) const;

}  // namespace glint
