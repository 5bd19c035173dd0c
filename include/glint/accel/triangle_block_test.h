#pragma once
/// \file The watertight triangle test on SIMD lanes: the four triangles of a leaf block at
/// once (SSE), or the eight of two blocks (AVX), the steps of `intersect_triangle_watertight`
/// in the same order, so that every lane finds what the scalar test finds. Its steps after
/// the shear (hit_sheared_lanes) also serve the packet test (triangle_bvh_packet.cpp).

#include "glint/geometry/triangle.h"
#include "glint/math/ray.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <array>
#include <cstdint>

namespace glint {

/// Four triangles, structure of arrays: v[vertex][axis][lane]. Unused lanes hold NaN
/// vertices, which the watertight test never reports.
struct alignas(32) TriangleBlock {
    static constexpr uint32_t kWidth = 4;
    float v[3][3][kWidth];
    uint32_t triangle[kWidth];
};
static_assert(sizeof(TriangleBlock) == 160);

namespace detail {

#if defined(__SSE2__)
/// `x`, hidden from the optimiser so that a product is rounded on its own, never fused.
inline __m128 opaque_float(__m128 x) {
    __asm__("" : "+x"(x));
    return x;
}
#if defined(__AVX__)
/// The same for eight lanes (the two-block test; the packet test, triangle_bvh_packet.cpp).
inline __m256 opaque_float(__m256 x) {
    __asm__("" : "+x"(x));
    return x;
}
#endif

/// a − b·c and a·b + c, rounded one way whatever the optimiser does: fused by explicit
/// instructions where the CPU has FMA, separately otherwise. The single-ray and the packet
/// triangle tests use them alike, so that both give every ray the same bits (with
/// -ffp-contract=fast the compiler would otherwise fuse some products in one and not in the
/// other, depending on the optimisation level).
inline __m128 minus_product(__m128 a, __m128 b, __m128 c) {
#if defined(__FMA__)
    return _mm_fnmadd_ps(b, c, a);
#else
    return _mm_sub_ps(a, opaque_float(_mm_mul_ps(b, c)));
#endif
}
inline __m128 plus_product(__m128 a, __m128 b, __m128 c) {
#if defined(__FMA__)
    return _mm_fmadd_ps(a, b, c);
#else
    return _mm_add_ps(opaque_float(_mm_mul_ps(a, b)), c);
#endif
}
#if defined(__AVX__)
inline __m256 minus_product(__m256 a, __m256 b, __m256 c) {
#if defined(__FMA__)
    return _mm256_fnmadd_ps(b, c, a);
#else
    return _mm256_sub_ps(a, opaque_float(_mm256_mul_ps(b, c)));
#endif
}
inline __m256 plus_product(__m256 a, __m256 b, __m256 c) {
#if defined(__FMA__)
    return _mm256_fmadd_ps(a, b, c);
#else
    return _mm256_add_ps(opaque_float(_mm256_mul_ps(a, b)), c);
#endif
}
#endif

/// The operations of the lane test for one register width: `FourLanes` for a block's four
/// triangles, `EightLanes` for two blocks' eight. (Tags rather than the register types
/// themselves as template arguments: those carry attributes a template argument drops.)
struct FourLanes {
    using V = __m128;
    static __m128 splat(float x) { return _mm_set1_ps(x); }
    static __m128 add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
    static __m128 sub(__m128 a, __m128 b) { return _mm_sub_ps(a, b); }
    static __m128 mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
    static __m128 min(__m128 a, __m128 b) { return _mm_min_ps(a, b); }
    static __m128 max(__m128 a, __m128 b) { return _mm_max_ps(a, b); }
    static __m128 less(__m128 a, __m128 b) { return _mm_cmplt_ps(a, b); }
    static __m128 greater(__m128 a, __m128 b) { return _mm_cmpgt_ps(a, b); }
    static __m128 both(__m128 a, __m128 b) { return _mm_and_ps(a, b); }
    static __m128 and_not(__m128 a, __m128 b) { return _mm_andnot_ps(a, b); }
    static __m128 flip(__m128 a, __m128 b) { return _mm_xor_ps(a, b); }
    static __m128 reciprocal(__m128 a) { return _mm_div_ps(_mm_set1_ps(1.0f), a); }
    static constexpr uint32_t kAllLanes = 0xf;
    static uint32_t mask(__m128 a) { return static_cast<uint32_t>(_mm_movemask_ps(a)); }
    static void store(float* out, __m128 a) { _mm_storeu_ps(out, a); }
    template <int Lane>
    static __m128 broadcast_lane(__m128 a) {
        return _mm_shuffle_ps(a, a, Lane * 0x55);
    }
};

#if defined(__AVX__)
struct EightLanes {
    using V = __m256;
    static __m256 splat(float x) { return _mm256_set1_ps(x); }
    static __m256 add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
    static __m256 sub(__m256 a, __m256 b) { return _mm256_sub_ps(a, b); }
    static __m256 mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
    static __m256 min(__m256 a, __m256 b) { return _mm256_min_ps(a, b); }
    static __m256 max(__m256 a, __m256 b) { return _mm256_max_ps(a, b); }
    static __m256 less(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
    static __m256 greater(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
    static __m256 both(__m256 a, __m256 b) { return _mm256_and_ps(a, b); }
    static __m256 and_not(__m256 a, __m256 b) { return _mm256_andnot_ps(a, b); }
    static __m256 flip(__m256 a, __m256 b) { return _mm256_xor_ps(a, b); }
    static __m256 reciprocal(__m256 a) { return _mm256_div_ps(_mm256_set1_ps(1.0f), a); }
    static constexpr uint32_t kAllLanes = 0xff;
    static uint32_t mask(__m256 a) { return static_cast<uint32_t>(_mm256_movemask_ps(a)); }
    static void store(float* out, __m256 a) { _mm256_storeu_ps(out, a); }
    template <int Lane>
    static __m256 broadcast_lane(__m128 a) {
        const __m128 lane = _mm_shuffle_ps(a, a, Lane * 0x55);
        return _mm256_set_m128(lane, lane);
    }
};

/// For each kz, the lanes that play the roles (kx, ky, kz, unused) in LaneRay's permutes.
alignas(16) inline constexpr auto kRoleLanes = [] {
    std::array<std::array<int32_t, 4>, 3> roles{};
    for (int kz = 0; kz < 3; ++kz) {
        const int kx = WatertightRay::kNextAxis[kz];
        roles[kz] = {kx, WatertightRay::kNextAxis[kx], kz, 3};
    }
    return roles;
}();
#endif

/// The watertight test's per-ray constants broadcast to L's lanes. It keeps no copy of the
/// ray: its caller has just written the ray field by field, and the copy read it back 32
/// bytes at once, a load the CPU cannot take from those stores and waits on; in half the runs
/// of `glint-bench` (as the program's addresses fell) the bunny's camera rays then traced at
/// 0.97-1.00 of Embree instead of 1.32 (docs/performance.md, "Fresh memory on an idle
/// machine").
template <typename L>
struct LaneRay {
    /// WatertightRay's axes: kz where the direction is largest, kx and ky after it.
    int kx, ky, kz;
    typename L::V ox, oy, oz, sx, sy, sz;
#if defined(__AVX__)
    /// WatertightRay's arithmetic on SIMD registers, the same numbers in fewer instructions:
    /// the direction's and the origin's components permuted into the roles kx, ky, kz at
    /// once (each component read on its own, see above), one division, one product for both
    /// shears (with kx, ky no longer swapped, single camera rays +2 to +3.5 %:
    /// docs/performance.md, "The watertight set-up on SIMD registers").
    explicit LaneRay(const Ray& ray) : kz(WatertightRay::dominant_axis(ray.direction)) {
        kx = WatertightRay::kNextAxis[kz];
        ky = WatertightRay::kNextAxis[kx];
        const __m128i roles = _mm_load_si128(reinterpret_cast<const __m128i*>(kRoleLanes[kz].data()));
        const __m128 d = _mm_permutevar_ps(_mm_setr_ps(ray.direction.x, ray.direction.y, ray.direction.z, 1.0f), roles);
        const __m128 o = _mm_permutevar_ps(_mm_setr_ps(ray.origin.x, ray.origin.y, ray.origin.z, 0.0f), roles);
        const __m128 shear_z = _mm_div_ps(_mm_set1_ps(1.0f), _mm_shuffle_ps(d, d, 0xaa));
        const __m128 shear = _mm_mul_ps(d, shear_z);
        ox = L::template broadcast_lane<0>(o);
        oy = L::template broadcast_lane<1>(o);
        oz = L::template broadcast_lane<2>(o);
        sx = L::template broadcast_lane<0>(shear);
        sy = L::template broadcast_lane<1>(shear);
        sz = L::template broadcast_lane<0>(shear_z);
    }
    /// The same constants on another width (the any-hit pair test's from the block test's).
    template <typename Other>
    explicit LaneRay(const LaneRay<Other>& r)
        : kx(r.kx),
          ky(r.ky),
          kz(r.kz),
          ox(L::template broadcast_lane<0>(r.ox)),
          oy(L::template broadcast_lane<0>(r.oy)),
          oz(L::template broadcast_lane<0>(r.oz)),
          sx(L::template broadcast_lane<0>(r.sx)),
          sy(L::template broadcast_lane<0>(r.sy)),
          sz(L::template broadcast_lane<0>(r.sz)) {}
#else
    explicit LaneRay(const Ray& ray) : LaneRay(WatertightRay(ray.direction), ray.origin) {}
    /// The origin's components are read one by one and picked by index, as WatertightRay
    /// picks the direction's.
    LaneRay(const WatertightRay& w, const Vec3& o)
        : kx(w.kx), ky(w.ky), kz(w.kz), sx(L::splat(w.sx)), sy(L::splat(w.sy)), sz(L::splat(w.sz)) {
        const float origin[3] = {glint::opaque_float(o.x), glint::opaque_float(o.y), glint::opaque_float(o.z)};
        ox = L::splat(origin[kx]);
        oy = L::splat(origin[ky]);
        oz = L::splat(origin[kz]);
    }
#endif
};
using BlockRay = LaneRay<FourLanes>;

/// A triangle's vertices translated to the ray origin and sheared (the ray along +z), on
/// L's lanes: x[k], y[k], z[k] of vertex k, as the scalar test's ax, ay, az, bx, ...
template <typename L>
struct ShearedTriangle {
    typename L::V x[3], y[3], z[3];
};

/// The rest of intersect_triangle_watertight once the vertices are sheared, on every lane of
/// L: the edge functions, the inside test, the depth test against (tmin, tmax), and for the
/// lanes that hit, t and the barycentrics of vertices 1 and 2. The one copy of these steps
/// for every SIMD form of the test: a block's triangles against one ray (intersect_lanes)
/// and one triangle against a packet's rays (triangle_bvh_packet.cpp), so both give a ray
/// the same bits. `sz` is the ray's shear of z.
///
/// With LeaveWhenAllOutside, returns 0 as soon as no lane is inside the edges, skipping the
/// depth test: that pays where the branch is predicted (closest-hit packets: eight coherent
/// camera rays mostly miss a triangle together). Elsewhere the edge test's verdict joins the
/// depth test's in one mask: for rays that leave a surface, whether some lane passes the
/// edges (the triangle the ray starts on does) changes from leaf to leaf, and the
/// mispredicted branch cost more than the depth test it skipped (single rays +2 to +11 %,
/// shadow packets +5 to +19 %: docs/performance.md, "One branch in the leaf test").
template <typename L, bool LeaveWhenAllOutside = false>
[[gnu::always_inline]] inline uint32_t hit_sheared_lanes(const ShearedTriangle<L>& p, typename L::V sz,
                                                         typename L::V tmin, typename L::V tmax, typename L::V& t_out,
                                                         typename L::V& u_out, typename L::V& v_out) {
    using V = typename L::V;
    // Edge functions as differences of two rounded products; opaque_float keeps the
    // compiler from fusing them into an FMA, so the two triangles sharing an edge compute
    // exactly opposite values for it (the heart of the watertightness argument).
    auto edge = [&](int i, int j) {
        return L::sub(opaque_float(L::mul(p.x[i], p.y[j])), opaque_float(L::mul(p.y[i], p.x[j])));
    };
    const V u = edge(2, 1);
    const V v = edge(0, 2);
    const V w = edge(1, 0);
    const V zero = L::splat(0.0f);
    // A miss has edge functions of both signs; zeros count as inside.
    const V lowest = L::min(L::min(u, v), w), highest = L::max(L::max(u, v), w);
    const V outside = L::both(L::less(lowest, zero), L::greater(highest, zero));
    if constexpr (LeaveWhenAllOutside) {
        if (L::mask(outside) == L::kAllLanes) return 0;
    }
    const V det = L::add(L::add(u, v), w);
    const V t_scaled =
        plus_product(w, L::mul(sz, p.z[2]), plus_product(v, L::mul(sz, p.z[1]), L::mul(u, L::mul(sz, p.z[0]))));
    // Compare t·|det| with the interval scaled by |det| and divide only for hits (the
    // paper's deferred division). det = 0 (zero-area triangles) fails the strict test,
    // unused (NaN) lanes fail every comparison.
    const V sign_mask = L::splat(-0.0f);
    const V det_sign = L::both(det, sign_mask);
    const V abs_det = L::and_not(sign_mask, det);
    const V t_abs = L::flip(t_scaled, det_sign);
    const V in_range = L::both(L::greater(t_abs, L::mul(abs_det, tmin)), L::less(t_abs, L::mul(abs_det, tmax)));
    const uint32_t mask = L::mask(L::and_not(outside, L::both(in_range, L::greater(abs_det, zero))));
    if (mask == 0) return 0;
    const V inv_det = L::reciprocal(det);
    t_out = L::mul(t_scaled, inv_det);
    u_out = L::mul(v, inv_det);
    v_out = L::mul(w, inv_det);
    return mask;
}

/// intersect_triangle_watertight on every lane of L at once, the same steps in the same order
/// (products fused by minus_product/plus_product where the CPU has FMA): `vertex(k, axis)`
/// loads component `axis` of vertex k of each lane's triangle. Returns the lanes that hit
/// within (tmin, tmax) and writes their t and barycentrics.
template <typename L, typename Vertex>
inline uint32_t intersect_lanes(const Vertex& vertex, const LaneRay<L>& r, float tmin, float tmax, float* t_out,
                                float* u_out, float* v_out) {
    ShearedTriangle<L> p;
    for (int k = 0; k < 3; ++k) {
        p.z[k] = L::sub(vertex(k, r.kz), r.oz);
        p.x[k] = minus_product(L::sub(vertex(k, r.kx), r.ox), r.sx, p.z[k]);
        p.y[k] = minus_product(L::sub(vertex(k, r.ky), r.oy), r.sy, p.z[k]);
    }
    typename L::V t, u, v;
    const uint32_t mask = hit_sheared_lanes(p, r.sz, L::splat(tmin), L::splat(tmax), t, u, v);
    if (mask == 0) return 0;
    L::store(t_out, t);
    L::store(u_out, u);
    L::store(v_out, v);
    return mask;
}
#else
/// The watertight test's per-ray constants.
struct BlockRay {
    Ray ray;
    WatertightRay w;
    explicit BlockRay(const Ray& ray_) : ray(ray_), w(ray.direction) {}
};
#endif

/// The four triangles of a block: the lanes that hit, their t and barycentrics.
inline uint32_t intersect_block(const TriangleBlock& b, const BlockRay& r, float tmin, float tmax, float* t_out,
                                float* u_out, float* v_out) {
#if defined(__SSE2__)
    return intersect_lanes([&](int k, int axis) { return _mm_load_ps(b.v[k][axis]); }, r, tmin, tmax, t_out, u_out,
                           v_out);
#else
    uint32_t mask = 0;
    for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
        Vec3 p[3];
        for (int vtx = 0; vtx < 3; ++vtx) p[vtx] = Vec3(b.v[vtx][0][lane], b.v[vtx][1][lane], b.v[vtx][2][lane]);
        TriangleHit th;
        if (intersect_triangle_watertight(r.ray, r.w, p[0], p[1], p[2], th) && th.t > tmin && th.t < tmax) {
            t_out[lane] = th.t;
            u_out[lane] = th.v;
            v_out[lane] = th.w;
            mask |= 1u << lane;
        }
    }
    return mask;
#endif
}

#if defined(__AVX__)
/// The eight triangles of two blocks at once (lanes 0-3 of `a`, 4-7 of `b`): two leaves that
/// a node hands on together take one test instead of two (docs/performance.md, "Two leaves
/// in one test").
inline uint32_t intersect_block_pair(const TriangleBlock& a, const TriangleBlock& b, const LaneRay<EightLanes>& r,
                                     float tmin, float tmax, float* t_out, float* u_out, float* v_out) {
    return intersect_lanes([&](int k, int axis) { return _mm256_loadu2_m128(b.v[k][axis], a.v[k][axis]); }, r, tmin,
                           tmax, t_out, u_out, v_out);
}
#endif

}  // namespace detail

}  // namespace glint
