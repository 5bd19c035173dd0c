#include "glint/integrators/whitted_integrator.h"

#include "glint/integrators/delta_light_shadows.h"
#include "glint/integrators/medium_absorption.h"
#include "glint/integrators/shading_point.h"
#include "glint/lights/area_light.h"
#include "glint/materials/normal_map.h"
#include "glint/math/offset_ray.h"
#include "glint/scene/render_scene.h"
#include "whitted_sampling.h"

#include <array>
#include <cmath>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint {

using whitted::power_heuristic;
using whitted::stratified_set;

namespace {

/// Room for a HitShading, left uninitialised: an array of std::optional<HitShading>, GCC 12
/// zero-fills (2.4 KB for each packet of first hits, 0.6 % of the dragon scene's time).
union UninitializedShading {
    UninitializedShading() {}
    HitShading value;
};
static_assert(std::is_trivially_destructible_v<HitShading>);

/// `ray` as its closest-hit query left it: ending at its hit, `t`.
Ray ray_to_hit(const Ray& ray, float t) {
    Ray r = ray;
    r.tmax = t;
    return r;
}

}  // namespace

std::unique_ptr<Integrator> WhittedIntegrator::create(const RenderSettings& settings) {
    return std::make_unique<WhittedIntegrator>(settings.max_depth, settings.light_samples, settings.glossy_samples);
}

Color WhittedIntegrator::Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const {
    return trace(scene, ray, 0, IorStack(scene.ambient_ior()), context);
}

void WhittedIntegrator::Li_given_first_hits(const RenderScene& scene, const FirstHits& first,
                                            std::span<TraceContext> contexts, std::span<Color> radiance) const {
    const IorStack media(scene.ambient_ior());
    const auto count = uint32_t(first.rays.size());
    // Lane k up to its hit: false if that is all (explain's lanes, which record their rays
    // from the start, and misses).
    auto start_lane = [&](uint32_t k) {
        TraceContext& context = contexts[k];
        if (context.tree) {
            radiance[k] = Li(scene, first.rays[k], context);
            return false;
        }
        context.glossy_origin.pdf = 0.0f;
        ++context.rays;
        if (first.hit(k)) return true;
        radiance[k] = radiance_from_hit<false>(scene, first.rays[k], nullptr, 0, media, -1, context);
        return false;
    };
    if (!scene.packets_pay()) {
        for (uint32_t k = 0; k < count; ++k) {
            if (!start_lane(k)) continue;
            const Hit hit = first.hits.hit(k);
            radiance[k] = radiance_from_hit<false>(scene, first.rays[k], &hit, 0, media, -1, contexts[k]);
        }
        return;
    }
    // Every hit's point first, then the shadow rays of all toward each delta light as packets.
    std::array<SurfaceInteraction, RayPacket::kSize> interactions = per_lane([&](uint32_t k) {
        if (k >= count || !first.hit(k)) return SurfaceInteraction();
        return scene.interaction(ray_to_hit(first.rays[k], first.hits.t[k]), first.hits.hit(k));
    });
    const std::array<DeltaLightShadows, RayPacket::kSize> shadows =
        trace_delta_light_shadows(scene, interactions, first.hit_lanes);
    // Then each hit's shading up to the rays that leave it, and their mirror rays as one
    // packet: a flat floor's reflections are as coherent as the camera rays that hit it.
    // Hits on blended per-vertex materials are shaded whole, their mirror rays one by one.
    std::array<UninitializedShading, RayPacket::kSize> shading;
    uint32_t shaded_lanes = 0;
    std::array<const Material*, RayPacket::kSize> materials;
    std::array<Color, RayPacket::kSize> kept;
    std::array<Ray, RayPacket::kSize> mirror_rays;
    RayPacket mirrors;
    for (uint32_t k = 0; k < count; ++k) {
        SurfaceInteraction& si = interactions[k];
        if (!first.hit(k) || contexts[k].tree || si.blends_materials) continue;
        kept[k] = begin_hit<false>(scene, first.rays[k], first.hits.hit(k), si, media, -1, contexts[k]);
        materials[k] = &scene.material(si.materials[0]);
        const Material& m = *materials[k];
        apply_normal_map(si, m);
        const HitShading& local = *std::construct_at(&shading[k].value, si, m, first.rays[k], media);
        shaded_lanes |= 1u << k;
        if (max_depth_ > 0 && local.reflects()) {
            mirror_rays[k] = local.reflected_ray(si);
            mirrors.set(k, mirror_rays[k]);
        }
    }
    PacketHits mirror_hits;
    const uint32_t mirror_hit_lanes = mirrors.active ? scene.intersect_packet(mirrors, mirror_hits) : 0;
    for (uint32_t k = 0; k < count; ++k) {
        if (!start_lane(k)) continue;
        TraceContext& context = contexts[k];
        const Hit hit = first.hits.hit(k);
        context.first_hit_shadows = &shadows[k];
        if (!(shaded_lanes >> k & 1)) {
            radiance[k] = shade_hit<false, true>(scene, first.rays[k], hit, interactions[k], 0, media, -1, context);
        } else {
            Hit mirror_hit;
            if (mirrors.active >> k & 1) {
                if (mirror_hit_lanes >> k & 1) mirror_hit = mirror_hits.hit(k);
                context.first_hit_mirror = {&mirror_rays[k], (mirror_hit_lanes >> k & 1) ? &mirror_hit : nullptr};
            }
            radiance[k] = kept[k] * shade_with<false, true>(scene, first.rays[k], hit.object, interactions[k],
                                                            *materials[k], shading[k].value, 0, media, context);
            context.first_hit_mirror = {};
        }
        context.first_hit_shadows = nullptr;
    }
}

Color WhittedIntegrator::trace(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                               TraceContext& context) const {
    context.glossy_origin.pdf = 0.0f;  // not a glossy sample's ray
    return context.tree ? trace_ray<true>(scene, ray, depth, media, context)
                        : trace_ray<false>(scene, ray, depth, media, context);
}

Color WhittedIntegrator::glossy_emission_weight(const RenderScene& scene, uint32_t object, const SurfaceInteraction& si,
                                                const TraceContext& context, const Color& emission) const {
    const GlossyOrigin& origin = context.glossy_origin;
    const AreaLight* light = scene.area_light_of(object);
    if (!(origin.pdf > 0.0f) || !light) return emission;
    const float light_pdf = light->pdf(origin.point, si.p, si.geometric_normal);
    return emission * power_heuristic(float(origin.samples) * origin.pdf, float(light_samples_) * light_pdf);
}

Color WhittedIntegrator::glossy_background_weight(const RenderScene& scene, const Ray& ray, const TraceContext& context,
                                                  const Color& background) const {
    const GlossyOrigin& origin = context.glossy_origin;
    const EnvironmentLight* light = scene.environment_light();
    if (!light || !scene.environment_lighting()) return background;
    const float light_pdf = light->pdf_direction(ray.direction, origin.normal);
    return background * power_heuristic(float(origin.samples) * origin.pdf, float(light_samples_) * light_pdf);
}

template <bool Record>
Color WhittedIntegrator::glossy(const RenderScene& scene, const Bsdf& bsdf, const SurfaceInteraction& si,
                                const ShadingPoint& sp, float ior, uint32_t count, uint32_t depth,
                                const IorStack& media, TraceContext& context) const {
    const int32_t node = Record ? context.node : -1;
    // The direction from one stratified set, the lobe (conductor or dielectric, reflection or
    // refraction) from the first coordinate of another, as for area-light samples.
    std::array<Vec2, 16> small_u, small_lobe;
    std::vector<Vec2> large_u, large_lobe;
    const std::span<Vec2> us = stratified_set(context.sampler, count, small_u, large_u);
    const std::span<Vec2> lobes = stratified_set(context.sampler, count, small_lobe, large_lobe);
    Color weight(1.0f);
    if constexpr (Record) weight = context.tree->nodes()[std::size_t(node)].weight;
    const bool was_below = context.below_glossy;
    context.below_glossy = true;
    const RayCone outgoing = context.cone;
    const float share = 1.0f / float(count);
    Color sum;
    for (uint32_t i = 0; i < count; ++i) {
        const std::optional<BsdfSample> s = bsdf.sample_glossy(lobes[i].x, us[i]);
        if (!s) continue;
        const Color w = s->weight * share;
        const bool transmitted = (s->flags & kBsdfTransmission) != 0;
        // A refracted sample enters or leaves the material's medium, as the delta refraction does.
        const IorStack beyond =
            transmitted ? (sp.entering ? media.entered(sp.medium, ior) : media.left(sp.medium)) : media;
        context.glossy_origin = {si.p, s->pdf, count, bsdf.normal()};
        context.cone = outgoing;
        if constexpr (Record)
            context.branch = {transmitted ? RayKind::GlossyTransmission : RayKind::GlossyReflection, node, weight * w};
        const Vec3 origin = offset_ray_origin(si.p, transmitted ? -sp.ng : sp.ng);
        sum += w * trace_ray<Record>(scene, Ray(origin, s->wi, 0.0f, kInfinity, si.time), depth + 1, beyond, context);
    }
    context.below_glossy = was_below;
    return sum;
}

template <bool Record>
Color WhittedIntegrator::trace_ray(const RenderScene& scene, Ray ray, uint32_t depth, const IorStack& media,
                                   TraceContext& context) const {
    ++context.rays;
    int32_t node = -1;
    if constexpr (Record) {
        const RayBranch& branch = context.branch;
        node = context.tree->add_ray(branch.kind, branch.parent, depth, ray, branch.weight);
        context.node = node;
    }
    // Traced where its caller built it, not in a copy: the copy read the new ray back as one
    // block before its field-by-field stores had reached the cache, a stall (store
    // forwarding) of every mirror ray (docs/performance.md). intersect() moves only tmax,
    // which radiance_from_hit() sets to the hit's t anyway.
    Hit hit;
    const bool found = scene.intersect(ray, hit);
    return radiance_from_hit<Record>(scene, ray, found ? &hit : nullptr, depth, media, node, context);
}

template <bool Record>
Color WhittedIntegrator::radiance_from_hit(const RenderScene& scene, const Ray& ray, const Hit* found, uint32_t depth,
                                           const IorStack& media, int32_t node, TraceContext& context) const {
    if (!found) {
        Color background = scene.background().evaluate(ray.direction);
        // A glossy sample that escapes finds what the environment light's samples find too.
        if (context.glossy_origin.pdf > 0.0f) background = glossy_background_weight(scene, ray, context, background);
        if constexpr (Record) context.tree->add_radiance(node, background);
        return background;
    }
    SurfaceInteraction si = scene.interaction(ray_to_hit(ray, found->t), *found);
    return shade_hit<Record>(scene, ray, *found, si, depth, media, node, context);
}

template <bool Record>
Color WhittedIntegrator::begin_hit(const RenderScene& scene, const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                                   const IorStack& media, int32_t node, TraceContext& context) const {
    // The ray's cone where it hit sets the texture footprint; the rays leaving here carry it
    // on, bounced (shade restores it for each). Only textures read it.
    if (scene.reads_texture_coordinates()) {
        const RayCone cone = context.cone.at(hit.t * length(ray.direction));
        si.uv_footprint = cone.uv_footprint(si, ray.direction);
        context.cone = cone.bounced(si.curvature);
    }
    if constexpr (Record) context.tree->set_hit(node, hit.t, hit.object, si.materials[0], Vec3());
    // Inside an absorbing dielectric the radiance from the hit loses exp(−σa·d) on the way.
    return transmittance(scene, media, hit.t);
}

template <bool Record, bool TracedAhead>
Color WhittedIntegrator::shade_hit(const RenderScene& scene, const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                                   uint32_t depth, const IorStack& media, int32_t node, TraceContext& context) const {
    const Color kept = begin_hit<Record>(scene, ray, hit, si, media, node, context);
    // Only hits on per-vertex materials build a (blended) Material.
    if (si.blends_materials) {
        const Material blended = blended_material(scene, si);
        apply_normal_map(si, blended);
        return kept * shade<Record, TracedAhead>(scene, ray, hit.object, si, blended, depth, media, context);
    }
    const Material& m = scene.material(si.materials[0]);
    apply_normal_map(si, m);
    return kept * shade<Record, TracedAhead>(scene, ray, hit.object, si, m, depth, media, context);
}

template <bool Record, bool TracedAhead>
Color WhittedIntegrator::shade(const RenderScene& scene, const Ray& ray, uint32_t object, const SurfaceInteraction& si,
                               const Material& m, uint32_t depth, const IorStack& media, TraceContext& context) const {
    return shade_with<Record, TracedAhead>(scene, ray, object, si, m, HitShading(si, m, ray, media), depth, media,
                                           context);
}

template <bool Record, bool TracedAhead>
Color WhittedIntegrator::shade_with(const RenderScene& scene, const Ray& ray, uint32_t object,
                                    const SurfaceInteraction& si, const Material& m, const HitShading& local,
                                    uint32_t depth, const IorStack& media, TraceContext& context) const {
    const ShadingPoint& sp = local.sp;
    const MaterialAtHit& at = local.at;
    const Bsdf& bsdf = local.bsdf;
    // The cone every ray leaving here starts with (each child's trace moves context.cone on).
    const RayCone outgoing = context.cone;
    // The ray being shaded (context.node changes as the children are traced).
    const int32_t node = Record ? context.node : -1;
    if constexpr (Record) context.tree->set_normal(node, sp.n);
    if (depth == 0 && context.first_hit) record_first_hit(*context.first_hit, ray, si, sp, m, at);

    Color radiance = scene.emitted(object, m, si, sp.wo);
    // Emission that a glossy sample found on an area light shares the light's samples' MIS.
    if (context.glossy_origin.pdf > 0.0f && !radiance.is_black())
        radiance = glossy_emission_weight(scene, object, si, context, radiance);
    const float t = std::clamp(m.transparency, 0.0f, 1.0f);
    if (t < 1.0f) {
        // Whitted's ambient term: ka·La, textured like the diffuse term; no BSDF lobe.
        radiance += at.ambient * scene.ambient_light() * (1.0f - t);
        if constexpr (Record) context.tree->add_radiance(node, radiance);
    } else if constexpr (Record) {
        context.tree->add_radiance(node, radiance);
    }
    // Glossy samples to trace from here: glossy_samples at the first rough surface, one below it.
    const uint32_t glossy_count =
        bsdf.has_glossy_lobes() && depth < max_depth_ ? (context.below_glossy ? 1 : glossy_samples_) : 0;
    // A clear dielectric (t = 1) takes no diffuse light (handout §6.2); its highlight and a
    // rough one's glossy lobes do.
    if (t < 1.0f || bsdf.has_smooth_lobes())
        radiance += direct_light<Record, TracedAhead>(scene, bsdf, si, sp.ng, glossy_count, context);
    if (depth >= max_depth_) return radiance;

    // The throughput from the camera to the children, for the tree only.
    Color weight(1.0f);
    if constexpr (Record) weight = context.tree->nodes()[std::size_t(node)].weight;
    const SpecularLobes& specular = bsdf.specular();
    if (local.reflects()) {
        if constexpr (Record) context.branch = {RayKind::Reflection, node, weight * specular.reflection};
        context.glossy_origin.pdf = 0.0f;
        context.cone = outgoing;
        // A first hit's mirror ray may have been traced already, with its neighbours': the
        // ray local.reflected_ray(si) makes, from this very `local` (never when recording).
        TracedRay traced;
        if constexpr (TracedAhead) traced = std::exchange(context.first_hit_mirror, TracedRay{});
        Color mirrored;
        if (traced.ray) {
            ++context.rays;
            mirrored = radiance_from_hit<false>(scene, *traced.ray, traced.hit, depth + 1, media, -1, context);
        } else {
            mirrored = trace_ray<Record>(scene, local.reflected_ray(si), depth + 1, media, context);
        }
        radiance += specular.reflection * mirrored;
    }
    if (specular.transmission > 0.0f && specular.refracted) {
        const IorStack inside = sp.entering ? media.entered(sp.medium, m.ior) : media.left(sp.medium);
        if constexpr (Record) context.branch = {RayKind::Refraction, node, weight * specular.transmission};
        context.glossy_origin.pdf = 0.0f;
        context.cone = outgoing;
        const Vec3 origin = offset_ray_origin(si.p, -sp.ng);
        radiance += trace_ray<Record>(scene, Ray(origin, *specular.refracted, 0.0f, kInfinity, si.time), depth + 1,
                                      inside, context) *
                    specular.transmission;
    }
    if (glossy_count > 0) {
        if constexpr (Record) context.node = node;
        context.cone = outgoing;
        radiance += glossy<Record>(scene, bsdf, si, sp, m.ior, glossy_count, depth, media, context);
    }
    return radiance;
}

}  // namespace glint
