#pragma once
/// \file glTF 2.0's metallic-roughness base layer on Glint's lobes (glTF 2.0, Appendix B):
/// one Schlick-Fresnel GGX lobe whose F0 is the base colour for metal and 4% for the
/// dielectric part, F0 = mix(0.04, base, metallic), beside the dielectric part's Lambertian
/// diffuse base·(1 − metallic). The glTF loader applies it to a material's factors, and a
/// material with a metallicRoughnessTexture to the values at each hit
/// (materials/material_at_hit.h): one formula, so that equal values give equal bits.

#include "glint/math/color.h"

namespace glint {

struct MetallicRoughnessLobes {
    /// kd: metal has no diffuse part.
    Color diffuse;
    /// kr, Schlick's F0 of the material's `fresnel_mirror`.
    Color reflectivity;
};

/// `dielectric_f0`: the non-metal part's F0, 4 % unless KHR_materials_ior or
/// KHR_materials_specular change it (Material::dielectric_f0).
[[nodiscard]] inline MetallicRoughnessLobes metallic_roughness_lobes(const Color& base, float metallic,
                                                                     const Color& dielectric_f0 = Color(0.04f)) {
    return {base * (1.0f - metallic), lerp(metallic, dielectric_f0, base)};
}

}  // namespace glint
