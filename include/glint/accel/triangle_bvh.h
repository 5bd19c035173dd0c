#pragma once
/// \file The bottom-level structure of a triangle mesh: an 8-wide BVH whose leaves hold up
/// to four triangles (one block), copied in leaf order and tested together with SSE
/// (x86-64; other targets test them one by one with the scalar watertight test).
///
/// One block per leaf was measured on the shared meshes: leaves of two or four blocks save
/// 10% memory but cost up to 15% on incoherent rays.
///
/// Copying the vertices (36 bytes per triangle, plus the index) into the leaves costs
/// memory but saves the index indirection and its cache misses on every leaf visit; the
/// SAH counts leaf cost in blocks of four, so few slots are wasted (Embree's Triangle4
/// leaves store more: the edges and the normal as well).

#include "glint/accel/ray_packet.h"
#include "glint/accel/wide_bvh.h"
#include "glint/geometry/hit.h"
#include "glint/geometry/triangle.h"
#include "glint/util/huge_page_array.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <span>
#include <type_traits>

namespace glint {

/// Four triangles, structure of arrays: v[vertex][axis][lane]. Unused lanes hold NaN
/// vertices, which the watertight test never reports.
struct alignas(32) TriangleBlock {
    static constexpr uint32_t kWidth = 4;
    float v[3][3][kWidth];
    uint32_t triangle[kWidth];
};
static_assert(sizeof(TriangleBlock) == 160);

/// A filter that takes every hit: the traversal compiles without the filter call.
struct AcceptAllHits {
    constexpr bool operator()(uint32_t, float, float) const { return true; }
};

class TriangleBvh {
public:
    /// Builds over the triangles (three indices each) in the caller's TBB arena; zero-area
    /// triangles are kept in the leaves but never reported.
    void build(std::span<const Vec3> positions, std::span<const uint32_t> indices);

    /// Closest (or with AnyHit, any) hit with t in (ray.tmin, ray.tmax). On a hit sets
    /// ray.tmax and hit.t, hit.primitive (the triangle), hit.u, hit.v (barycentrics of
    /// vertices 1 and 2). `accept(triangle, u, v) -> bool` may reject a hit (alpha
    /// masks); rejected hits do not end the query.
    /// `count` (traversal_count.h) counts nodes and triangles for the viewer's heatmaps.
    template <bool AnyHit, typename Filter = AcceptAllHits, typename Count = NoTraversalCount>
    bool intersect(Ray& ray, Hit& hit, Filter&& accept = {}, const Count& count = {}) const;

    /// intersect<false> for the packet's active lanes at once (triangle_bvh_packet.cpp):
    /// returns the lanes that hit, shrinks their tmax and writes their hits. The same
    /// watertight arithmetic per lane, so each lane finds the hit a single ray would (at a
    /// tie between triangles at one t, possibly the other one). No filter, no counting.
    uint32_t intersect_packet(RayPacket& packet, PacketHits& hits) const;
    /// intersect<true> for the packet's active lanes: returns the lanes that hit anything.
    [[nodiscard]] uint32_t occluded_packet(const RayPacket& packet) const;

    /// True before build() (or after building over no triangles).
    [[nodiscard]] bool empty() const { return blocks_.empty(); }
    /// Box of all triangles.
    [[nodiscard]] Bounds3 bounds() const { return wide_.bounds(); }
    /// The nodes; a leaf reference is the index of the leaf's block.
    [[nodiscard]] const WideBvh& wide_bvh() const { return wide_; }
    /// The leaf blocks, in traversal order.
    [[nodiscard]] std::span<const TriangleBlock> blocks() const { return blocks_; }
    /// Bytes of nodes and leaf blocks (the mesh's own arrays not included).
    [[nodiscard]] std::size_t memory_bytes() const {
        return wide_.memory_bytes() + blocks_.size() * sizeof(TriangleBlock);
    }

private:
    WideBvh wide_;
    // Every ray reads them: in huge pages from 2 MiB on (huge_page_array.h).
    HugePageArray<TriangleBlock> blocks_;
};

namespace detail {

#if defined(__SSE2__)
/// `x`, hidden from the optimiser so that a product is rounded on its own, never fused.
inline __m128 opaque_float(__m128 x) {
    __asm__("" : "+x"(x));
    return x;
}
#if defined(__AVX__)
/// The same for eight lanes (the packet test, triangle_bvh_packet.cpp).
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

/// The watertight test's per-ray constants broadcast for four lanes. It keeps no copy of
/// the ray: its caller has just written the ray field by field, and the copy read it back
/// 32 bytes at once, a load the CPU cannot take from those stores and waits on; in half the
/// runs of `glint-bench` (as the program's addresses fell) the bunny's camera rays then
/// traced at 0.97-1.00 of Embree instead of 1.32 (docs/performance.md, "Fresh memory on an
/// idle machine").
struct BlockRay {
    WatertightRay w;
    __m128 ox, oy, oz, sx, sy, sz;
    explicit BlockRay(const Ray& ray)
        : w(ray.direction),
          ox(_mm_set1_ps(ray.origin[w.kx])),
          oy(_mm_set1_ps(ray.origin[w.ky])),
          oz(_mm_set1_ps(ray.origin[w.kz])),
          sx(_mm_set1_ps(w.sx)),
          sy(_mm_set1_ps(w.sy)),
          sz(_mm_set1_ps(w.sz)) {}
};
#else
/// The watertight test's per-ray constants.
struct BlockRay {
    Ray ray;
    WatertightRay w;
    explicit BlockRay(const Ray& ray_) : ray(ray_), w(ray.direction) {}
};
#endif

/// intersect_triangle_watertight for four triangles at once, the same steps in the same
/// order (products fused by minus_product/plus_product where the CPU has FMA); returns the
/// lanes that hit and writes their t and barycentrics.
inline uint32_t intersect_block(const TriangleBlock& b, const BlockRay& r, float tmin, float tmax, float* t_out,
                                float* u_out, float* v_out) {
#if defined(__SSE2__)
    // Sheared, translated vertices in float, as in the scalar test.
    auto sheared = [&](int vertex, __m128& x, __m128& y, __m128& z) {
        z = _mm_sub_ps(_mm_load_ps(b.v[vertex][r.w.kz]), r.oz);
        x = minus_product(_mm_sub_ps(_mm_load_ps(b.v[vertex][r.w.kx]), r.ox), r.sx, z);
        y = minus_product(_mm_sub_ps(_mm_load_ps(b.v[vertex][r.w.ky]), r.oy), r.sy, z);
    };
    __m128 ax, ay, az, bx, by, bz, cx, cy, cz;
    sheared(0, ax, ay, az);
    sheared(1, bx, by, bz);
    sheared(2, cx, cy, cz);
    // Edge functions as differences of two rounded products; opaque_float keeps the
    // compiler from fusing them into an FMA, so the two triangles sharing an edge compute
    // exactly opposite values for it (the heart of the watertightness argument).
    auto edge = [](__m128 px, __m128 py, __m128 qx, __m128 qy) {
        return _mm_sub_ps(opaque_float(_mm_mul_ps(px, qy)), opaque_float(_mm_mul_ps(py, qx)));
    };
    const __m128 u = edge(cx, cy, bx, by);
    const __m128 v = edge(ax, ay, cx, cy);
    const __m128 w = edge(bx, by, ax, ay);
    const __m128 zero = _mm_setzero_ps();
    // A miss has edge functions of both signs; zeros count as inside.
    const __m128 lowest = _mm_min_ps(_mm_min_ps(u, v), w), highest = _mm_max_ps(_mm_max_ps(u, v), w);
    int mask = ~_mm_movemask_ps(_mm_and_ps(_mm_cmplt_ps(lowest, zero), _mm_cmpgt_ps(highest, zero))) & 0xf;
    if (mask == 0) return 0;
    const __m128 det = _mm_add_ps(_mm_add_ps(u, v), w);
    const __m128 t_scaled = plus_product(
        w, _mm_mul_ps(r.sz, cz), plus_product(v, _mm_mul_ps(r.sz, bz), _mm_mul_ps(u, _mm_mul_ps(r.sz, az))));
    // Compare t·|det| with the interval scaled by |det| and divide only for hits (the
    // paper's deferred division). det = 0 (zero-area triangles) fails the strict test,
    // unused (NaN) lanes fail every comparison.
    const __m128 sign_mask = _mm_set1_ps(-0.0f);
    const __m128 det_sign = _mm_and_ps(det, sign_mask);
    const __m128 abs_det = _mm_andnot_ps(sign_mask, det);
    const __m128 t_abs = _mm_xor_ps(t_scaled, det_sign);
    const __m128 in_range = _mm_and_ps(_mm_cmpgt_ps(t_abs, _mm_mul_ps(abs_det, _mm_set1_ps(tmin))),
                                       _mm_cmplt_ps(t_abs, _mm_mul_ps(abs_det, _mm_set1_ps(tmax))));
    mask &= _mm_movemask_ps(_mm_and_ps(in_range, _mm_cmpgt_ps(abs_det, zero)));
    if (mask == 0) return 0;
    const __m128 inv_det = _mm_div_ps(_mm_set1_ps(1.0f), det);
    const __m128 t = _mm_mul_ps(t_scaled, inv_det);
    _mm_storeu_ps(t_out, t);
    _mm_storeu_ps(u_out, _mm_mul_ps(v, inv_det));
    _mm_storeu_ps(v_out, _mm_mul_ps(w, inv_det));
    return static_cast<uint32_t>(mask);
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

}  // namespace detail

template <bool AnyHit, typename Filter, typename Count>
bool TriangleBvh::intersect(Ray& ray, Hit& hit, Filter&& accept, const Count& count) const {
    constexpr bool kFiltered = !std::is_same_v<std::decay_t<Filter>, AcceptAllHits>;
    const detail::BlockRay block_ray(ray);
    auto intersect_leaf = [&](uint32_t leaf, Ray& r) {
        const TriangleBlock& block = blocks_[leaf];
        if constexpr (!std::is_same_v<Count, NoTraversalCount>) {
            uint64_t real = 0;  // padding lanes hold kNoHit
            for (const uint32_t triangle : block.triangle) real += triangle != kNoHit;
            count.primitives(real);
        }
        float t[4], u[4], v[4];
        uint32_t mask = detail::intersect_block(block, block_ray, r.tmin, r.tmax, t, u, v);
        // Take the nearest lane that the filter accepts (any accepted lane for AnyHit).
        while (mask) {
            auto best = static_cast<uint32_t>(std::countr_zero(mask));
            if constexpr (!AnyHit)
                for (uint32_t m = mask & (mask - 1); m; m &= m - 1) {
                    const auto i = static_cast<uint32_t>(std::countr_zero(m));
                    if (t[i] < t[best]) best = i;
                }
            if constexpr (kFiltered) {
                if (!accept(block.triangle[best], u[best], v[best])) {
                    mask &= ~(1u << best);
                    continue;
                }
            }
            r.tmax = t[best];
            hit.t = t[best];
            hit.primitive = block.triangle[best];
            hit.u = u[best];
            hit.v = v[best];
            return true;
        }
        return false;
    };
    return wide_.traverse<AnyHit>(ray, intersect_leaf, count);
}

}  // namespace glint
