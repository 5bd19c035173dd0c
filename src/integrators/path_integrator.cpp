#include "glint/integrators/path_integrator.h"

#include "glint/integrators/medium_absorption.h"
#include "glint/integrators/shading_point.h"
#include "glint/materials/normal_map.h"
#include "glint/math/offset_ray.h"
#include "glint/scene/render_scene.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint {

namespace {

/// Bounces before Russian roulette may end a path.
constexpr uint32_t kRouletteDepth = 3;

}  // namespace

std::unique_ptr<Integrator> PathIntegrator::create(const RenderSettings& settings) {
    return std::make_unique<PathIntegrator>(settings.max_depth, settings.mis);
}

std::vector<std::string> PathIntegrator::warnings(const RenderScene& scene) const {
    std::vector<std::string> out;
    if (!scene.ambient_light().is_black())
        out.emplace_back(
            "the path integrator ignores [world] ambient_light: ambient is a Whitted term; light comes from lights, "
            "emission and the background");
    return out;
}

float PathIntegrator::mis_weight(float pdf_a, float pdf_b) const {
    if (heuristic_ == MisHeuristic::Balance) return pdf_a / (pdf_a + pdf_b);
    const float a2 = pdf_a * pdf_a, b2 = pdf_b * pdf_b;
    return a2 / (a2 + b2);
}

Color PathIntegrator::Li(const RenderScene& scene, const Ray& camera_ray, TraceContext& context) const {
    Sampler& sampler = context.sampler;
    const std::vector<const Light*>& lights = scene.all_lights();
    const float light_choice_pdf = lights.empty() ? 0.0f : 1.0f / float(lights.size());

    Color radiance, throughput(1.0f);
    Ray ray = camera_ray;
    IorStack media(scene.ambient_ior());
    // The previous bounce: was it a delta lobe, its BSDF density and where it was.
    bool specular_bounce = true;
    float bsdf_pdf = 0.0f;
    Vec3 previous_point, previous_normal;

    // The ray of the path in context.tree, if one is recorded.
    int32_t node = -1;
    // The cone of `ray` (integrators/ray_cone.h), for texture footprints.
    RayCone cone = context.cone;

    for (uint32_t depth = 0;; ++depth) {
        ++context.rays;
        if (context.tree)
            node = context.tree->add_ray(depth == 0 ? RayKind::Camera : RayKind::Bounce, node, depth, ray, throughput);
        Ray r = ray;
        Hit hit;
        if (!scene.intersect(r, hit)) {
            // The environment light samples the background too: after a non-delta bounce, what
            // BSDF sampling finds takes the power heuristic's share (Veach 1997, eq. 9.13).
            Color background = scene.background().evaluate(ray.direction);
            if (const EnvironmentLight* environment = scene.environment_light(); environment && !specular_bounce)
                background *=
                    mis_weight(bsdf_pdf, light_choice_pdf * environment->pdf_direction(ray.direction, previous_normal));
            radiance += throughput * background;
            if (context.tree) context.tree->add_radiance(node, background);
            break;
        }
        SurfaceInteraction si = scene.interaction(r, hit);
        if (scene.reads_texture_coordinates()) {
            cone = cone.at(r.tmax * length(ray.direction));
            si.uv_footprint = cone.uv_footprint(si, ray.direction);
        }
        // Inside an absorbing dielectric the path loses exp(−σa·d) on the way here.
        throughput *= transmittance(scene, media, r.tmax);
        // Only hits on per-vertex materials pay for a blended copy.
        std::optional<Material> blended;
        if (si.blends_materials) blended = blended_material(scene, si);
        const Material& m = blended ? *blended : scene.material(si.materials[0]);
        apply_normal_map(si, m);
        const ShadingPoint sp = shading_point(si, m, ray, media);
        if (context.tree) context.tree->set_hit(node, r.tmax, hit.object, si.materials[0], sp.n);
        if (depth == 0 && context.first_hit)
            record_first_hit(*context.first_hit, camera_ray, si, sp, m, material_at_hit(m, si));

        const Color le = scene.emitted(hit.object, m, si, sp.wo);
        if (!le.is_black()) {
            const AreaLight* light = scene.area_light_of(hit.object);
            float weight = 1.0f;
            if (light && !specular_bounce)
                weight = mis_weight(bsdf_pdf, light_choice_pdf * light->pdf(previous_point, si.p, si.geometric_normal));
            radiance += throughput * le * weight;
            if (context.tree) context.tree->add_radiance(node, le * weight);
        }
        if (depth >= max_depth_) break;

        const Bsdf bsdf(m, material_at_hit(m, si), sp.n, sp.ng, sp.wo, sp.media);

        // Next-event estimation: one light, chosen uniformly.
        const float u_light = sampler.next_1d();
        const Vec2 u_light_point = sampler.next_2d();
        if (bsdf.has_smooth_lobes() && !lights.empty()) {
            const auto chosen = std::min(std::size_t(u_light * float(lights.size())), lights.size() - 1);
            const Light& light = *lights[chosen];
            const LightSample ls = light.sample_at_surface(si.p, sp.n, u_light_point);
            if (ls.pdf > 0.0f && !ls.radiance.is_black()) {
                const Color f = bsdf.eval(ls.direction);
                if (!f.is_black()) {
                    ++context.rays;
                    // Light under the surface (a rough dielectric's transmission) is sampled
                    // from that side.
                    const Ray shadow = shadow_ray(si.p, dot(ls.direction, sp.ng) < 0.0f ? -sp.ng : sp.ng, ls, si.time);
                    const bool blocked = scene.occluded(shadow, DielectricShadows::Opaque);
                    Color direct;
                    if (!blocked) {
                        const float pdf = light_choice_pdf * ls.pdf;
                        const float weight = ls.is_delta ? 1.0f : mis_weight(pdf, bsdf.pdf(ls.direction));
                        const float scale = std::abs(dot(sp.n, ls.direction)) * weight / pdf;
                        radiance += throughput * f * ls.radiance * scale;
                        if (context.tree) direct = f * ls.radiance * scale;
                    }
                    if (context.tree) context.tree->add_shadow_ray(node, shadow, uint32_t(chosen), blocked, direct);
                }
            }
        }

        // Continue the path by sampling the BSDF.
        const float u_lobe = sampler.next_1d();
        const Vec2 u_direction = sampler.next_2d();
        const std::optional<BsdfSample> bs = bsdf.sample(u_lobe, u_direction);
        if (!bs) break;
        throughput *= bs->weight;
        specular_bounce = (bs->flags & kBsdfDelta) != 0;
        bsdf_pdf = bs->pdf;
        previous_point = si.p;
        previous_normal = sp.n;
        if (scene.reads_texture_coordinates()) cone = cone.bounced(si.curvature);
        if (bs->flags & kBsdfTransmission) {
            media = sp.entering ? media.entered(sp.medium, m.ior) : media.left(sp.medium);
            ray = Ray(offset_ray_origin(si.p, -sp.ng), bs->wi, 0.0f, kInfinity, si.time);
        } else {
            ray = Ray(offset_ray_origin(si.p, sp.ng), bs->wi, 0.0f, kInfinity, si.time);
        }

        // Russian roulette (Arvo & Kirk 1990): unbiased, since survivors are reweighted.
        const float u_roulette = sampler.next_1d();
        if (depth + 1 >= kRouletteDepth) {
            const float survive = std::min(0.95f, throughput.max_component());
            if (!(u_roulette < survive)) break;
            throughput *= 1.0f / survive;
        }
    }
    return radiance;
}

}  // namespace glint
