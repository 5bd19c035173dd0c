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
    return trace(scene, ray, 0, IorStack(scene.ambient_ior()), context);
}

Color WhittedIntegrator::direct_light(const RenderScene& scene, const Bsdf& bsdf, const SurfaceInteraction& si,
                                      const Vec3& ng, TraceContext& context) const {
    const Vec3 origin = offset_ray_origin(si.p, ng);
    Color sum;
    auto add = [&](const LightSample& ls, float weight) {
        if (!(ls.pdf > 0.0f) || ls.radiance.is_black()) return;
        if (!bsdf.may_reflect(ls.direction)) return;  // behind the surface, or a glass with no smooth lobe
        ++context.rays;
        if (scene.occluded(shadow_ray(origin, ls))) return;
        sum += bsdf.eval(ls.direction) * ls.radiance * (dot(bsdf.normal(), ls.direction) * weight / ls.pdf);
    };
    for (const Light* light : scene.all_lights()) {
        if (light->is_delta()) {
            add(light->sample(si.p, Vec2()), 1.0f);
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
        for (const Vec2& u : us) add(light->sample(si.p, u), 1.0f / float(light_samples_));
    }
    return sum;
}

Color WhittedIntegrator::trace(const RenderScene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                               TraceContext& context) const {
    ++context.rays;
    Ray r = ray;
    Hit hit;
    if (!scene.intersect(r, hit)) return scene.background().evaluate(ray.direction);

    const SurfaceInteraction si = scene.interaction(r, hit);
    // Only hits on per-vertex materials build a (blended) Material.
    if (si.blends_materials) return shade(scene, ray, hit.object, si, blended_material(scene, si), depth, media, context);
    return shade(scene, ray, hit.object, si, scene.material(si.materials[0]), depth, media, context);
}

Color WhittedIntegrator::shade(const RenderScene& scene, const Ray& ray, uint32_t object, const SurfaceInteraction& si,
                               const Material& m, uint32_t depth, const IorStack& media, TraceContext& context) const {
    const ShadingPoint sp = shading_point(si, m, ray, media);
    const Color texture = diffuse_texture(m, si);
    const Bsdf bsdf(m, texture, sp.n, sp.ng, sp.wo, sp.media);

    Color radiance = scene.emitted(object, m, si, sp.wo);
    const float t = std::clamp(m.transparency, 0.0f, 1.0f);
    if (t < 1.0f) {
        // Whitted's ambient term: ka·La, textured like the diffuse term; no BSDF lobe.
        radiance += texture * m.ambient * scene.ambient_light() * (1.0f - t);
        radiance += direct_light(scene, bsdf, si, sp.ng, context);
    }
    if (depth >= max_depth_) return radiance;

    const SpecularLobes& specular = bsdf.specular();
    // A reflection that the shading normal bends below the true surface would start inside it.
    if (!specular.reflection.is_black() && dot(specular.reflected, sp.ng) > 0.0f) {
        const Ray reflected(offset_ray_origin(si.p, sp.ng), specular.reflected);
        radiance += specular.reflection * trace(scene, reflected, depth + 1, media, context);
    }
    if (specular.transmission > 0.0f && specular.refracted) {
        const IorStack inside = sp.entering ? media.entered(sp.medium, m.ior) : media.left(sp.medium);
        const Ray transmitted(offset_ray_origin(si.p, -sp.ng), *specular.refracted);
        radiance += trace(scene, transmitted, depth + 1, inside, context) * specular.transmission;
    }
    return radiance;
}

}  // namespace glint
