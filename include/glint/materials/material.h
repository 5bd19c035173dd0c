#pragma once
/// \file The Whitted material: one parameter set that covers both assignments' models.
///
/// Shading (docs/shading.md has the full derivation):
///   L = Le + (1 - t)·[ tex·(ka·La + Σ_i v_i·kd·E_i·max(N·L_i, 0))
///                      + Σ_i v_i·ks·(N·H_i)^s·E_i·max(N·L_i, 0) + kr·L_reflect ]
///          + t·[ F·L_reflect + (1 - F)·L_refract ]
/// t = transparency, F = Schlick's Fresnel term for the interface, v_i = visibility of light i;
/// a ray inside a dielectric loses exp(−σa·d) over a distance d (`absorption`).
/// The handout's opaque material is t = 0 with kr = its "specular" colour; its dielectric
/// is t = 1. The seminar's reflectivity r and transparency τ are kr = r and t = τ.

#include "glint/materials/texture.h"
#include "glint/math/color.h"

#include <string>

namespace glint {

class BuildContext;
class ParamTable;

struct Material {
    std::string name;
    /// ka: reflectance of the scene's ambient light.
    Color ambient{0.0f};
    /// kd: Lambertian reflectance of direct light.
    Color diffuse{0.8f};
    /// Multiplies the ambient + diffuse direct term (the handout's t_p); null for none.
    const Texture* texture = nullptr;
    /// ks and s of the optional Blinn-Phong highlight ks·(N·H)^s; black for none.
    Color specular{0.0f};
    float shininess = 32.0f;
    /// kr: weight of the recursive mirror reflection.
    Color reflectivity{0.0f};
    /// If true, the mirror weight is Schlick's F with F0 = kr (a metal: tinted reflection
    /// that whitens at grazing angles) instead of the constant kr.
    bool fresnel_mirror = false;
    /// t: weight of the dielectric part (Fresnel-mixed reflection and refraction). 0 = opaque.
    float transparency = 0.0f;
    /// Index of refraction of the dielectric.
    float ior = 1.5f;
    /// σa, the Beer-Lambert absorption coefficient inside the dielectric, per scene unit:
    /// light that crosses a distance d inside keeps exp(−σa·d) of itself, so a thick glass
    /// tints more than a thin one. Black: clear. (KHR_materials_volume: σa =
    /// −ln(attenuationColor) / attenuationDistance.)
    Color absorption{0.0f};
    /// Le: emitted radiance. It lights other surfaces as an area light unless the scene's
    /// `emission_lights` is off (then it is only seen by rays that hit it).
    Color emission{0.0f};
    const Texture* emission_texture = nullptr;
    /// A tangent-space normal map (linear RGB: n = 2·rgb − 1, +x along the tangent, +y "up" in
    /// the image, +z along the surface normal; materials/normal_map.h) bending the shading
    /// normal; null for none. `normal_scale` scales its x and y (glTF's normalTexture.scale).
    const Texture* normal_texture = nullptr;
    float normal_scale = 1.0f;
    /// Cut-out mask: hits where texture alpha < alpha_cutoff are skipped, shadow rays too.
    const Texture* alpha_texture = nullptr;
    float alpha_cutoff = 0.5f;
    /// Microfacet roughness in [0, 1]. 0: the mirror and the dielectric are Dirac deltas (exact
    /// reflection and refraction). Above 0 they become GGX lobes of alpha = roughness²
    /// (glossy metal, frosted glass; materials/microfacet.h).
    float roughness = 0.0f;
    /// glTF's metallicRoughnessTexture (glTF 2.0, §3.9.2); null for none. With one, kd, ka, kr
    /// and the roughness vary over the surface (materials/material_at_hit.h): the texture's
    /// blue channel times `metallic` is the metalness and its green channel times `roughness`
    /// the roughness at a hit, and kd = ka = base·(1 − metalness), kr = mix(0.04, base,
    /// metalness) with base = base_color × `texture` (materials/metallic_roughness.h). The
    /// ambient, diffuse and reflectivity above then only describe the factors.
    const Texture* metallic_roughness_texture = nullptr;
    /// glTF's baseColorFactor and metallicFactor, which the texture above needs at each hit.
    Color base_color{1.0f};
    float metallic = 1.0f;
    /// glTF's F0 of the non-metal part: ((ior − 1)/(ior + 1))² (0.04 at 1.5; KHR_materials_ior)
    /// tinted by KHR_materials_specular's colour and scaled by its factor.
    Color dielectric_f0{0.04f};

    [[nodiscard]] bool is_dielectric() const { return transparency > 0.0f; }
    /// Whether any of the textures above is set: only they read a hit's texture coordinates.
    [[nodiscard]] bool has_textures() const {
        return texture || emission_texture || normal_texture || alpha_texture || metallic_roughness_texture;
    }

    /// The scene-file factory of `type = "standard"` (docs/scene-format.md): every key
    /// above but `name`; throws SceneError at a bad one.
    [[nodiscard]] static Material standard_from_params(const ParamTable& params, const BuildContext& context);
};

/// Barycentric blend of three materials' numeric parameters (per-vertex materials,
/// handout §6.1.1). Textures and flags come from the corner with the largest weight.
[[nodiscard]] Material blend(const Material& a, const Material& b, const Material& c, float wa, float wb, float wc);

}  // namespace glint
