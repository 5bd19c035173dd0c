#include "glint/materials/material.h"

namespace glint {

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
    return m;
}

}  // namespace glint
