#include "glint/materials/material.h"

#include "glint/scene_format/build_context.h"

#include <fmt/format.h>

#include <cmath>

namespace glint {

namespace {

float unit_interval(const ParamTable& t, std::string_view key, float fallback, std::string_view what) {
    const float x = t.number(key, fallback);
    if (x < 0.0f || x > 1.0f) t.fail(key, fmt::format("{} from 0 to 1", what));
    return x;
}

/// `absorption` (σa per scene unit), or `attenuation_color` (what is left of white light
/// after `attenuation_distance`, default 1 scene unit; KHR_materials_volume's terms).
void read_absorption(const ParamTable& t, Material& m) {
    if (t.find("absorption") && t.find("attenuation_color"))
        t.fail("attenuation_color", "either absorption or attenuation_color, not both");
    m.absorption = t.color("absorption", m.absorption);
    if (t.find("attenuation_distance") && !t.find("attenuation_color"))
        t.fail("attenuation_distance", "attenuation_color beside it (the colour left after this distance)");
    if (!t.find("attenuation_color")) return;
    const Color left = t.color("attenuation_color", Color(1.0f));
    const float distance = t.number("attenuation_distance", 1.0f);
    if (!(distance > 0.0f)) t.fail("attenuation_distance", "a positive distance in scene units");
    for (int c = 0; c < 3; ++c)
        if (!(left[c] > 0.0f && left[c] <= 1.0f))
            t.fail("attenuation_color", "a colour with components in (0, 1]: what is left of white light");
    m.absorption = {-std::log(left.r) / distance, -std::log(left.g) / distance, -std::log(left.b) / distance};
}

}  // namespace

Material blend(const Material& a, const Material& b, const Material& c, float wa, float wb, float wc) {
    const Material& dominant = (wa >= wb && wa >= wc) ? a : (wb >= wc ? b : c);
    Material m = dominant;
    auto mix = [&](auto Material::*field) { return a.*field * wa + b.*field * wb + c.*field * wc; };
    m.ambient = mix(&Material::ambient);
    m.diffuse = mix(&Material::diffuse);
    m.specular = mix(&Material::specular);
    m.shininess = mix(&Material::shininess);
    m.reflectivity = mix(&Material::reflectivity);
    m.transparency = mix(&Material::transparency);
    m.ior = mix(&Material::ior);
    m.emission = mix(&Material::emission);
    m.roughness = mix(&Material::roughness);
    m.base_color = mix(&Material::base_color);
    m.metallic = mix(&Material::metallic);
    m.absorption = mix(&Material::absorption);
    m.dielectric_f0 = mix(&Material::dielectric_f0);
    return m;
}

Material Material::standard_from_params(const ParamTable& t, const BuildContext& context) {
    Material m;
    m.ambient = t.color("ambient", m.ambient);
    m.diffuse = t.color("diffuse", m.diffuse);
    m.texture = context.texture(t, "texture");
    m.specular = t.color("specular", m.specular);
    m.shininess = t.number("shininess", m.shininess);
    if (m.shininess < 0.0f) t.fail("shininess", "a non-negative Blinn-Phong exponent");
    m.reflectivity = t.color("reflectivity", m.reflectivity);
    m.fresnel_mirror = t.boolean("fresnel_mirror", m.fresnel_mirror);
    m.emission = t.color("emission", m.emission);
    m.emission_texture = context.texture(t, "emission_texture");
    m.alpha_texture = context.texture(t, "alpha_texture");
    m.normal_texture = context.texture(t, "normal_texture");
    if (m.normal_texture && m.normal_texture->channel_count() < 3)
        t.fail("normal_texture", "a texture of tangent-space normals with three channels (RGB); this one has " +
                                     std::to_string(m.normal_texture->channel_count()));
    m.normal_scale = t.number("normal_scale", m.normal_scale);
    if (!std::isfinite(m.normal_scale)) t.fail("normal_scale", "a finite number");
    m.alpha_cutoff = unit_interval(t, "alpha_cutoff", m.alpha_cutoff, "a coverage threshold");
    m.roughness = unit_interval(t, "roughness", m.roughness, "a roughness");

    // Two ways to say "dielectric": the seminar's transparency + ior, or the handout's
    // refraction_index alone (0 = opaque, otherwise a clear dielectric of that index).
    const ParamValue* handout_ior = t.find("refraction_index");
    const ParamValue* transparency = t.find("transparency");
    const ParamValue* ior = t.find("ior");
    if (handout_ior) {
        if (transparency || ior)
            t.fail("refraction_index",
                   "either refraction_index (the handout's model) or transparency and ior, not both");
        const float n = handout_ior->as_float(t.name_of("refraction_index"));
        if (n < 0.0f) t.fail("refraction_index", "0 for an opaque material or a positive index of refraction");
        m.transparency = n > 0.0f ? 1.0f : 0.0f;
        if (n > 0.0f) m.ior = n;
    } else {
        m.transparency = unit_interval(t, "transparency", 0.0f, "a transparency");
        if (ior) {
            m.ior = ior->as_float(t.name_of("ior"));
            if (m.ior < 0.0f) t.fail("ior", "a positive index of refraction (or 0 for opaque)");
            if (m.ior == 0.0f && m.transparency > 0.0f)
                t.fail("ior", "a positive index of refraction for a transparent material (ior = 0 means opaque)");
            if (m.ior == 0.0f) m.ior = 1.0f;
        }
    }
    read_absorption(t, m);
    return m;
}

}  // namespace glint
