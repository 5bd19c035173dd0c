#include "glint/materials/material_at_hit.h"

#include "glint/materials/metallic_roughness.h"

#include <algorithm>

namespace glint {

MaterialAtHit metallic_roughness_at(const Material& m, Color base_texture, const TextureQuery& q) {
    // glTF 2.0, material.pbrMetallicRoughness.metallicRoughnessTexture (§3.9.2): metalness in
    // the blue channel, roughness in the green, linear values (the loader reads the image as
    // data, not sRGB) that multiply metallicFactor and roughnessFactor; red and alpha are
    // not part of it (occlusion often shares the image's red channel).
    const Color texel = m.metallic_roughness_texture->evaluate(q);
    // Clamped like the loader's factors: a float (EXR) texture may hold values past 1.
    const float metallic = std::clamp(m.metallic * texel.b, 0.0f, 1.0f);
    const float roughness = std::clamp(m.roughness * texel.g, 0.0f, 1.0f);
    // The base colour is factor × texture (§3.9.2), so its texture tints F0 here as well as kd.
    const MetallicRoughnessLobes lobes = metallic_roughness_lobes(m.base_color * base_texture, metallic, m.dielectric_f0);
    // glTF has no ambient reflectance; the loader makes ka = kd, and so does each hit.
    return {lobes.diffuse, lobes.diffuse, lobes.reflectivity, roughness};
}

}  // namespace glint
