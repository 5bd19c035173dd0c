#pragma once
/// \file Ray-triangle intersection.

#include "glint/math/ray.h"
#include "glint/math/vec3.h"

#include <cmath>

namespace glint {

/// Result of a ray-triangle test: t and the barycentric weights (v, w) of v1 and v2
/// (the weight of v0 is 1 - v - w).
struct TriangleHit {
    float t;
    float v;
    float w;
};

/// `x`, hidden from the optimiser so that a product is rounded on its own, never fused
/// into a multiply-add.
[[nodiscard]] inline float opaque_float(float x) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __asm__("" : "+x"(x));
#else
    volatile float v = x;
    x = v;
#endif
    return x;
}

/// Per-ray constants of the watertight test: the axis kz where the direction is largest,
/// the other two (swapped when d[kz] < 0 to keep the winding), and the shear that maps the
/// direction onto +z.
///
/// Chosen without branches: a renderer's bounce rays point anywhere, and branches on their
/// direction were mispredicted about once a ray (incoherent rays +4 to +8 %, single camera
/// rays, whose branches were always predicted, -3 to -6 %: docs/performance.md, "The
/// watertight set-up without branches").
struct WatertightRay {
    int kx, ky, kz;
    float sx, sy, sz;
    explicit WatertightRay(const Vec3& d) {
        // Picked by index from an array, each component read on its own: one wide load of a
        // direction its caller has just written field by field would wait for those stores.
        const float dir[3] = {opaque_float(d.x), opaque_float(d.y), opaque_float(d.z)};
        const Vec3 ad = abs(d);
        const int x_over_y = ad.x > ad.y, x_over_z = ad.x > ad.z, y_over_z = ad.y > ad.z;
        kz = 2 - 2 * (x_over_y & x_over_z) - ((x_over_y ^ 1) & y_over_z);  // max_axis(ad)
        static constexpr int kNext[3] = {1, 2, 0};
        const int next = kNext[kz], after = kNext[next];
        const int swap = -int(dir[kz] < 0.0f);  // all bits set, or none
        kx = next ^ ((next ^ after) & swap);
        ky = after ^ ((next ^ after) & swap);
        // One division: the shear constants are per ray, shared by every triangle it meets,
        // so their rounding cannot open a gap between neighbours.
        sz = 1.0f / dir[kz];
        sx = dir[kx] * sz;
        sy = dir[ky] * sz;
    }
};

/// Watertight ray-triangle test (Woop, Benthin, Wald 2013, "Watertight Ray/Triangle
/// Intersection", JCGT 2(1)): the vertices are moved into a frame where the ray is the +z
/// axis, and the 2D edge functions U, V, W decide inside/outside. Two triangles sharing an
/// edge compute the same edge function for it, so no ray slips between them; an edge
/// function that rounds to zero counts as inside, so rays through edges and vertices hit
/// (possibly both neighbours). Accepts t strictly inside (tmin, tmax), either winding, and
/// never reports a zero-area triangle (U + V + W = 0). The SIMD leaf tests in
/// accel/triangle_bvh.h (four triangles at a time) and triangle_bvh_packet.cpp (eight rays at
/// a time) take the same steps, with fused multiply-adds where the CPU has them.
[[nodiscard]] inline bool intersect_triangle_watertight(const Ray& ray, const WatertightRay& w, const Vec3& v0,
                                                        const Vec3& v1, const Vec3& v2, TriangleHit& out) {
    const Vec3 a = v0 - ray.origin, b = v1 - ray.origin, c = v2 - ray.origin;
    const float ax = a[w.kx] - w.sx * a[w.kz], ay = a[w.ky] - w.sy * a[w.kz];
    const float bx = b[w.kx] - w.sx * b[w.kz], by = b[w.ky] - w.sy * b[w.kz];
    const float cx = c[w.kx] - w.sx * c[w.kz], cy = c[w.ky] - w.sy * c[w.kz];
    // Each edge function is a difference of two rounded products; opaque_float keeps the
    // compiler from fusing them into an FMA, so an edge shared by two triangles gives
    // exactly opposite values in the two (the paper's argument needs this).
    const float u = opaque_float(cx * by) - opaque_float(cy * bx);
    const float v = opaque_float(ax * cy) - opaque_float(ay * cx);
    const float wgt = opaque_float(bx * ay) - opaque_float(by * ax);
    if ((u < 0.0f || v < 0.0f || wgt < 0.0f) && (u > 0.0f || v > 0.0f || wgt > 0.0f)) return false;
    const float det = u + v + wgt;
    if (det == 0.0f) return false;
    const float t_scaled = u * (w.sz * a[w.kz]) + v * (w.sz * b[w.kz]) + wgt * (w.sz * c[w.kz]);
    const float inv_det = 1.0f / det;
    const float t = t_scaled * inv_det;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    out = {t, v * inv_det, wgt * inv_det};
    return true;
}

}  // namespace glint
