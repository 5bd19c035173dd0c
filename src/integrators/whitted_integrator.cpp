#include "glint/integrators/whitted_integrator.h"

#include "glint/integrators/optics.h"
#include "glint/math/offset_ray.h"
#include "glint/scene/scene.h"

#include <cmath>
#include <optional>

namespace glint {

Color WhittedIntegrator::Li(const Scene& scene, const Ray& ray, TraceContext& context) const {
    return trace(scene, ray, 0, IorStack(scene.ambient_ior), context);
}

Color WhittedIntegrator::direct_light(const Scene& scene, const Material& m, const SurfaceInteraction& si,
                                      const Vec3& to_viewer, const Vec3& n, TraceContext& context) const {
    const Vec3 ng = face_forward(si.geometric_normal, n);
    const Vec3 origin = offset_ray_origin(si.p, ng);
    Color diffuse_sum, highlight_sum;
    for (const auto& light : scene.lights()) {
        const LightSample ls = light->sample(si.p);
        const float cos_theta = dot(n, ls.direction);
        // Lights behind the shading or the true surface contribute nothing.
        if (cos_theta <= 0.0f || dot(ng, ls.direction) <= 0.0f || ls.irradiance.is_black()) continue;
        ++context.rays;
        if (scene.occluded(Ray(origin, ls.direction, 0.0f, ls.distance))) continue;
        const Color e_cos = ls.irradiance * cos_theta;
        diffuse_sum += e_cos;
        if (!m.specular.is_black()) {
            // Blinn-Phong: ks·(N·H)^s with the half-vector H of light and view directions.
            const Vec3 h = normalize(ls.direction + to_viewer);
            highlight_sum += e_cos * std::pow(std::max(dot(n, h), 0.0f), m.shininess);
        }
    }
    const Color texture = m.texture ? m.texture->evaluate(si.uv, si.p) : Color(1.0f);
    return texture * (m.ambient * scene.ambient_light + m.diffuse * diffuse_sum) + m.specular * highlight_sum;
}

Color WhittedIntegrator::trace(const Scene& scene, const Ray& ray, uint32_t depth, const IorStack& media,
                               TraceContext& context) const {
    ++context.rays;
    Ray r = ray;
    Hit hit;
    if (!scene.intersect(r, hit)) return scene.background.evaluate(ray.direction);

    const SurfaceInteraction si = scene.interaction(r, hit);
    const uint32_t material_index = si.materials[0];
    // Only hits on meshes with per-vertex materials pay for a blended copy.
    std::optional<Material> blended;
    if (si.blends_materials) {
        const auto& w = si.material_weights;
        blended = blend(scene.material(si.materials[0]), scene.material(si.materials[1]),
                        scene.material(si.materials[2]), w[0], w[1], w[2]);
    }
    const Material& m = blended ? *blended : scene.material(material_index);

    const Vec3 d = normalize(ray.direction);
    const Vec3 to_viewer = -d;
    // Shade on the side the ray arrived from (surfaces are two-sided).
    const bool entering = si.front_face;
    const Vec3 n = entering ? si.shading_normal : -si.shading_normal;
    const Vec3 ng = entering ? si.geometric_normal : -si.geometric_normal;

    Color radiance = m.emission;
    if (m.emission_texture) radiance *= m.emission_texture->evaluate(si.uv, si.p);

    const float t = std::clamp(m.transparency, 0.0f, 1.0f);
    if (t < 1.0f) radiance += direct_light(scene, m, si, to_viewer, n, context) * (1.0f - t);
    if (depth >= max_depth_) return radiance;

    const Vec3 reflect_origin = offset_ray_origin(si.p, ng);
    const Vec3 reflected_dir = reflect(d, n);
    // A reflection that the shading normal bends below the true surface would start inside it.
    const bool can_reflect = dot(reflected_dir, ng) > 0.0f;
    Color reflected;
    bool have_reflected = false;
    auto reflection = [&]() {
        if (!have_reflected) {
            reflected = can_reflect ? trace(scene, Ray(reflect_origin, reflected_dir), depth + 1, media, context) : Color();
            have_reflected = true;
        }
        return reflected;
    };

    if (t < 1.0f && !m.reflectivity.is_black()) {
        Color weight = m.reflectivity;
        if (m.fresnel_mirror) {
            // Schlick with a coloured F0 (metals): F = F0 + (1 - F0)(1 - cos θ)^5.
            const float c = 1.0f - std::clamp(dot(n, to_viewer), 0.0f, 1.0f);
            const float c5 = c * c * c * c * c;
            weight = m.reflectivity + (Color(1.0f) - m.reflectivity) * c5;
        }
        radiance += weight * reflection() * (1.0f - t);
    }

    if (t > 0.0f) {
        // Indices on both sides of the interface, from the stack of media (handout §5.4.1).
        const float eta_from = entering ? media.current() : m.ior;
        const float eta_to = entering ? m.ior : media.outside_of(material_index);
        const auto refracted = refract(d, n, eta_from, eta_to);
        if (!refracted) {
            radiance += reflection() * t;  // total internal reflection: R = 1
        } else {
            const float fresnel = fresnel_schlick(d, n, eta_from, eta_to);
            const IorStack inside = entering ? media.entered(material_index, m.ior) : media.left(material_index);
            const Ray transmitted(offset_ray_origin(si.p, -ng), *refracted);
            const Color lt = trace(scene, transmitted, depth + 1, inside, context);
            radiance += (reflection() * fresnel + lt * (1.0f - fresnel)) * t;
        }
    }
    return radiance;
}

}  // namespace glint
