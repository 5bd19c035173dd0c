#include "glint/integrators/whitted_integrator.h"

#include "glint/integrators/shading_point.h"
#include "glint/math/offset_ray.h"
#include "glint/scene/render_scene.h"

#include <array>
#include <cmath>
#include <vector>

namespace glint {

std::unique_ptr<Integrator> WhittedIntegrator::create(const RenderSettings& settings) {
    return std::make_unique<WhittedIntegrator>(settings.max_depth, settings.light_samples);
}

Color WhittedIntegrator::Li(const RenderScene& scene, const Ray& ray, TraceContext& context) const {
    const IorStack media(scene.ambient_ior());
    return context.tree ? trace_ray<true>(scene, ray, 0, media, context)
                        : trace_ray<false>(scene, ray, 0, media, context);
}

Color WhittedIntegrator::trace(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                               TraceContext& context) const {
    return context.tree ? trace_ray<true>(scene, ray, depth, media, context)
                        : trace_ray<false>(scene, ray, depth, media, context);
}

template <bool Record>
Color WhittedIntegrator::direct_light(const RenderScene& scene, const Bsdf& bsdf, const SurfaceInteraction& si,
                                      const Vec3& ng, TraceContext& context) const {
    const int32_t node = context.node;
    const Vec3 origin = offset_ray_origin(si.p, ng);
    Color sum;
    auto add = [&](const LightSample& ls, float weight, uint32_t light) {
        if (!(ls.pdf > 0.0f) || ls.radiance.is_black()) return;
        if (!bsdf.may_reflect(ls.direction)) return;  // behind the surface, or a glass with no smooth lobe
        ++context.rays;
        const Ray shadow = shadow_ray(origin, ls);
        if (scene.occluded(shadow)) {
            if constexpr (Record) context.tree->add_shadow_ray(node, shadow, light, true, Color());
            return;
        }
        const Color c = bsdf.eval(ls.direction) * ls.radiance * (dot(bsdf.normal(), ls.direction) * weight / ls.pdf);
        // The tree records what the sum gained, not c: recording c would give its product a
        // second use, and GCC then no longer fuses it into the sum (FMA) as it does in the
        // render's instantiation, so explain differed from render in the last bit.
        [[maybe_unused]] const Color before = sum;
        sum += c;
        if constexpr (Record) context.tree->add_shadow_ray(node, shadow, light, false, sum - before);
    };
    const std::vector<const Light*>& lights = scene.all_lights();
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const Light* light = lights[i];
        if (light->is_delta()) {
            add(light->sample(si.p, Vec2()), 1.0f, i);
            continue;
        }
        // N stratified samples of this light: the estimate (1/N) Σ f·L·cosθ/pdf.
        std::array<Vec2, 16> small;
        std::vector<Vec2> large;
        std::span<Vec2> us(small.data(), light_samples_);
        if (light_samples_ > small.size()) {
            large.resize(light_samples_);
            us = large;
        }
        context.sampler.next_2d_set(us);
        for (const Vec2& u : us) add(light->sample(si.p, u), 1.0f / float(light_samples_), i);
    }
    return sum;
}

template <bool Record>
Color WhittedIntegrator::trace_ray(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                                   TraceContext& context) const {
    ++context.rays;
    int32_t node = -1;
    if constexpr (Record) {
        const RayBranch& branch = context.branch;
        node = context.tree->add_ray(branch.kind, branch.parent, depth, ray, branch.weight);
        context.node = node;
    }
    Ray r = ray;
    Hit hit;
    if (!scene.intersect(r, hit)) {
        const Color background = scene.background().evaluate(ray.direction);
        if constexpr (Record) context.tree->add_radiance(node, background);
        return background;
    }

    const SurfaceInteraction si = scene.interaction(r, hit);
    if constexpr (Record) context.tree->set_hit(node, r.tmax, hit.object, si.materials[0], Vec3());
    // Only hits on per-vertex materials build a (blended) Material.
    if (si.blends_materials)
        return shade<Record>(scene, ray, hit.object, si, blended_material(scene, si), depth, media, context);
    return shade<Record>(scene, ray, hit.object, si, scene.material(si.materials[0]), depth, media, context);
}

template <bool Record>
Color WhittedIntegrator::shade(const RenderScene& scene, const Ray& ray, uint32_t object, const SurfaceInteraction& si,
                               const Material& m, uint32_t depth, const IorStack& media, TraceContext& context) const {
    const ShadingPoint sp = shading_point(si, m, ray, media);
    const Color texture = diffuse_texture(m, si);
    const Bsdf bsdf(m, texture, sp.n, sp.ng, sp.wo, sp.media);
    // The ray being shaded (context.node changes as the children are traced).
    const int32_t node = Record ? context.node : -1;
    if constexpr (Record) context.tree->set_normal(node, sp.n);
    if (depth == 0 && context.first_hit) record_first_hit(*context.first_hit, ray, si, sp, m, texture);

    Color radiance = scene.emitted(object, m, si, sp.wo);
    const float t = std::clamp(m.transparency, 0.0f, 1.0f);
    if (t < 1.0f) {
        // Whitted's ambient term: ka·La, textured like the diffuse term; no BSDF lobe.
        radiance += texture * m.ambient * scene.ambient_light() * (1.0f - t);
        if constexpr (Record) context.tree->add_radiance(node, radiance);
        radiance += direct_light<Record>(scene, bsdf, si, sp.ng, context);
    } else if constexpr (Record) {
        context.tree->add_radiance(node, radiance);
    }
    if (depth >= max_depth_) return radiance;

    // The throughput from the camera to the children, for the tree only.
    Color weight(1.0f);
    if constexpr (Record) weight = context.tree->nodes()[std::size_t(node)].weight;
    const SpecularLobes& specular = bsdf.specular();
    // A reflection that the shading normal bends below the true surface would start inside it.
    if (!specular.reflection.is_black() && dot(specular.reflected, sp.ng) > 0.0f) {
        const Ray reflected(offset_ray_origin(si.p, sp.ng), specular.reflected);
        if constexpr (Record) context.branch = {RayKind::Reflection, node, weight * specular.reflection};
        radiance += specular.reflection * trace_ray<Record>(scene, reflected, depth + 1, media, context);
    }
    if (specular.transmission > 0.0f && specular.refracted) {
        const IorStack inside = sp.entering ? media.entered(sp.medium, m.ior) : media.left(sp.medium);
        const Ray transmitted(offset_ray_origin(si.p, -sp.ng), *specular.refracted);
        if constexpr (Record) context.branch = {RayKind::Refraction, node, weight * specular.transmission};
        radiance += trace_ray<Record>(scene, transmitted, depth + 1, inside, context) * specular.transmission;
    }
    return radiance;
}

}  // namespace glint
