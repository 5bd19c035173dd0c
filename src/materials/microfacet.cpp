#include "glint/materials/microfacet.h"

#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

#include <cmath>

namespace glint {

float TrowbridgeReitz::D(const Vec3& wm) const {
    if (wm.z <= 0.0f) return 0.0f;
    const float x = wm.x / alpha_x_, y = wm.y / alpha_y_;
    const float s = x * x + y * y + wm.z * wm.z;
    return 1.0f / (kPi * alpha_x_ * alpha_y_ * s * s);
}

float TrowbridgeReitz::lambda(const Vec3& w) const {
    const float z2 = w.z * w.z;
    if (z2 == 0.0f) return kInfinity;
    // α(φ)² tan²θ = (αx² x² + αy² y²)/z².
    const float ax = alpha_x_ * w.x, ay = alpha_y_ * w.y;
    const float alpha2_tan2 = (ax * ax + ay * ay) / z2;
    return 0.5f * (std::sqrt(1.0f + alpha2_tan2) - 1.0f);
}

float TrowbridgeReitz::D(const Vec3& w, const Vec3& wm) const {
    const float cos_w = std::abs(w.z);
    // For w under the surface, the normals its mirror image above sees (sample_wm's flip).
    const float w_dot_wm = std::copysign(1.0f, w.z) * dot(w, wm);
    if (cos_w == 0.0f || w_dot_wm <= 0.0f) return 0.0f;
    return G1(w) / cos_w * D(wm) * w_dot_wm;
}

Vec3 TrowbridgeReitz::sample_wm(const Vec3& w, Vec2 u) const {
    // Heitz 2018, listing 1 with pbrt-v4's concentric disk. The view direction stretched into
    // the α = 1 configuration, where visible normals are the projected hemisphere.
    Vec3 wh = normalize(Vec3(alpha_x_ * w.x, alpha_y_ * w.y, w.z));
    if (wh.z < 0.0f) wh = -wh;
    // An orthonormal frame (t1, t2, wh); t1 is any tangent when wh is the normal.
    const float len2 = wh.x * wh.x + wh.y * wh.y;
    const Vec3 t1 = len2 > 0.0f ? Vec3(-wh.y, wh.x, 0.0f) / std::sqrt(len2) : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 t2 = cross(wh, t1);
    // A uniform disk point, its upper half squeezed towards the horizon seen from wh: the
    // projection of the half of the hemisphere behind the horizon is a half ellipse of
    // height wh.z (Heitz 2018, section 4).
    Vec2 p = sample_uniform_disk_concentric(u);
    const float h = std::sqrt(std::max(0.0f, 1.0f - p.x * p.x));
    const float s = 0.5f * (1.0f + wh.z);
    p.y = (1.0f - s) * h + s * p.y;
    // Lift onto the hemisphere about wh, then unstretch: normals transform by the inverse
    // transpose of the stretch (αx, αy, 1).
    const float pz = std::sqrt(std::max(0.0f, 1.0f - p.x * p.x - p.y * p.y));
    const Vec3 nh = t1 * p.x + t2 * p.y + wh * pz;
    return normalize(Vec3(alpha_x_ * nh.x, alpha_y_ * nh.y, std::max(1e-6f, nh.z)));
}

}  // namespace glint
