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

/// a − b·c and a·b + c, rounded one way whatever the compiler's contraction: fused where the
/// CPU has FMA, separately otherwise, as the SIMD tests round them (accel/triangle_block_test.h).
/// Left to -ffp-contract, the scalar test's shear was fused at some inlined call sites and not
/// at others: a heightfield and the same triangles in a mesh gave a ray different bits, and the
/// heightfield's result depended on the order of the axes (docs/performance.md, "The watertight
/// set-up on SIMD registers").
[[nodiscard]] inline float minus_product(float a, float b, float c) {
#if defined(__FMA__)
    return std::fma(-b, c, a);
#else
    return a - opaque_float(b * c);
#endif
}
[[nodiscard]] inline float plus_product(float a, float b, float c) {
#if defined(__FMA__)
    return std::fma(a, b, c);
#else
    return opaque_float(a * b) + c;
#endif
}

/// Per-ray constants of the watertight test: the axis kz where the direction is largest,
/// the other two in cyclic order, and the shear that maps the direction onto +z. (The paper
/// swaps kx and ky when d[kz] < 0 to keep the winding; a test that takes either winding does
/// not need to: the swap negates U, V, W, the determinant and the scaled t exactly, so t and
/// the barycentrics come out the same bits.)
///
/// Chosen without branches: a renderer's bounce rays point anywhere, and branches on their
/// direction were mispredicted about once a ray (incoherent rays +4 to +8 %, single camera
/// rays, whose branches were always predicted, -3 to -6 %: docs/performance.md, "The
/// watertight set-up without branches").
struct WatertightRay {
    /// The axis after each axis, cyclically: kx = kNextAxis[kz], ky = kNextAxis[kx]. Every
    /// form of the test (the SIMD lanes' role table, the packets' lane masks) follows this
    /// table, so that all of them shear a vertex the same way.
    static constexpr int kNextAxis[3] = {1, 2, 0};
    int kx, ky, kz;
    float sx, sy, sz;
    /// The axis where |d| is largest (max_axis's tie rules), without branches.
    [[nodiscard]] static int dominant_axis(const Vec3& d) {
        const Vec3 ad = abs(d);
        const int x_over_y = ad.x > ad.y, x_over_z = ad.x > ad.z, y_over_z = ad.y > ad.z;
        return 2 - 2 * (x_over_y & x_over_z) - ((x_over_y ^ 1) & y_over_z);
    }
    explicit WatertightRay(const Vec3& d) {
        // Picked by index from an array, each component read on its own: one wide load of a
        // direction its caller has just written field by field would wait for those stores.
        const float dir[3] = {opaque_float(d.x), opaque_float(d.y), opaque_float(d.z)};
        kz = dominant_axis(d);
        kx = kNextAxis[kz];
        ky = kNextAxis[kx];
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
/// accel/triangle_block_test.h (four or eight triangles at a time) and triangle_bvh_packet.cpp
/// (eight rays at a time) take the same steps and fuse the same products (minus_product,
/// plus_product), so a heightfield's triangles and a mesh's give a ray the same bits.
[[nodiscard]] inline bool intersect_triangle_watertight(const Ray& ray, const WatertightRay& w, const Vec3& v0,
                                                        const Vec3& v1, const Vec3& v2, TriangleHit& out) {
    const Vec3 a = v0 - ray.origin, b = v1 - ray.origin, c = v2 - ray.origin;
    const float ax = minus_product(a[w.kx], w.sx, a[w.kz]), ay = minus_product(a[w.ky], w.sy, a[w.kz]);
    const float bx = minus_product(b[w.kx], w.sx, b[w.kz]), by = minus_product(b[w.ky], w.sy, b[w.kz]);
    const float cx = minus_product(c[w.kx], w.sx, c[w.kz]), cy = minus_product(c[w.ky], w.sy, c[w.kz]);
    // Each edge function is a difference of two rounded products; opaque_float keeps the
    // compiler from fusing them into an FMA, so an edge shared by two triangles gives
    // exactly opposite values in the two (the paper's argument needs this).
    const float u = opaque_float(cx * by) - opaque_float(cy * bx);
    const float v = opaque_float(ax * cy) - opaque_float(ay * cx);
    const float wgt = opaque_float(bx * ay) - opaque_float(by * ax);
    if ((u < 0.0f || v < 0.0f || wgt < 0.0f) && (u > 0.0f || v > 0.0f || wgt > 0.0f)) return false;
    const float det = u + v + wgt;
    if (det == 0.0f) return false;
    const float t_scaled = plus_product(wgt, w.sz * c[w.kz], plus_product(v, w.sz * b[w.kz], u * (w.sz * a[w.kz])));
    const float inv_det = 1.0f / det;
    const float t = t_scaled * inv_det;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    out = {t, v * inv_det, wgt * inv_det};
    return true;
}

}  // namespace glint
