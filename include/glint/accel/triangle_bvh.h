#pragma once
/// \file The bottom-level structure of a triangle mesh: an 8-wide BVH whose leaves hold up
/// to four triangles, copied in leaf order and tested together with SSE.
///
/// Copying the vertices (36 bytes per triangle, plus the index) into the leaves costs
/// memory but saves the index indirection and its cache misses on every leaf visit; the
/// SAH counts leaf cost in blocks of four, so few slots are wasted (Embree's Triangle4
/// leaves store more: the edges and the normal as well).

#include "glint/accel/wide_bvh.h"
#include "glint/geometry/hit.h"
#include "glint/geometry/triangle.h"

#include <immintrin.h>

#include <span>
#include <type_traits>
#include <vector>

namespace glint {

/// Four triangles, structure of arrays: v[vertex][axis][lane]. Unused lanes are
/// zero-area triangles at the origin, which the watertight test never reports.
struct alignas(16) TriangleBlock {
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
    template <bool AnyHit, typename Filter = AcceptAllHits>
    bool intersect(Ray& ray, Hit& hit, Filter&& accept = {}) const;

    [[nodiscard]] bool empty() const { return blocks_.empty(); }
    [[nodiscard]] Bounds3 bounds() const { return wide_.bounds(); }
    [[nodiscard]] const WideBvh& wide_bvh() const { return wide_; }
    [[nodiscard]] std::span<const TriangleBlock> blocks() const { return blocks_; }
    /// Bytes of nodes and leaf blocks (the mesh's own arrays not included).
    [[nodiscard]] std::size_t memory_bytes() const {
        return wide_.memory_bytes() + blocks_.size() * sizeof(TriangleBlock);
    }

private:
    WideBvh wide_;
    std::vector<TriangleBlock> blocks_;
};

namespace detail {

/// The watertight test's per-ray constants broadcast for four lanes.
struct BlockRay {
    Ray ray;
    WatertightRay w;
    __m128 ox, oy, oz, sx, sy, sz;
    explicit BlockRay(const Ray& ray_)
        : ray(ray_), w(ray.direction), ox(_mm_set1_ps(ray.origin[w.kx])), oy(_mm_set1_ps(ray.origin[w.ky])),
          oz(_mm_set1_ps(ray.origin[w.kz])), sx(_mm_set1_ps(w.sx)), sy(_mm_set1_ps(w.sy)), sz(_mm_set1_ps(w.sz)) {}
};

/// intersect_triangle_watertight for four triangles at once, the same arithmetic in the
/// same order; returns the lanes that hit and writes their t and barycentrics.
inline uint32_t intersect_block(const TriangleBlock& b, const BlockRay& r, float tmin, float tmax, float* t_out,
                                float* u_out, float* v_out) {
#if defined(__AVX2__)
    // Sheared, translated vertices in float, as in the scalar test.
    auto sheared = [&](int vertex, __m128& x, __m128& y, __m128& z) {
        z = _mm_sub_ps(_mm_load_ps(b.v[vertex][r.w.kz]), r.oz);
        x = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(b.v[vertex][r.w.kx]), r.ox), _mm_mul_ps(r.sx, z));
        y = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(b.v[vertex][r.w.ky]), r.oy), _mm_mul_ps(r.sy, z));
    };
    __m128 ax, ay, az, bx, by, bz, cx, cy, cz;
    sheared(0, ax, ay, az);
    sheared(1, bx, by, bz);
    sheared(2, cx, cy, cz);
    // Edge functions in double: the float products are exact there, so an edge shared by
    // two triangles gives exactly opposite values whatever the compiler fuses into FMAs.
    auto edge = [](__m128 px, __m128 py, __m128 qx, __m128 qy) {
        return _mm256_sub_pd(_mm256_mul_pd(_mm256_cvtps_pd(px), _mm256_cvtps_pd(qy)),
                             _mm256_mul_pd(_mm256_cvtps_pd(py), _mm256_cvtps_pd(qx)));
    };
    const __m256d u = edge(cx, cy, bx, by);
    const __m256d v = edge(ax, ay, cx, cy);
    const __m256d w = edge(bx, by, ax, ay);
    const __m256d zero = _mm256_setzero_pd();
    // A miss has edge functions of both signs; zeros count as inside (watertightness).
    const __m256d negative = _mm256_or_pd(
        _mm256_or_pd(_mm256_cmp_pd(u, zero, _CMP_LT_OQ), _mm256_cmp_pd(v, zero, _CMP_LT_OQ)),
        _mm256_cmp_pd(w, zero, _CMP_LT_OQ));
    const __m256d positive = _mm256_or_pd(
        _mm256_or_pd(_mm256_cmp_pd(u, zero, _CMP_GT_OQ), _mm256_cmp_pd(v, zero, _CMP_GT_OQ)),
        _mm256_cmp_pd(w, zero, _CMP_GT_OQ));
    int mask = ~_mm256_movemask_pd(_mm256_and_pd(negative, positive)) & 0xf;
    if (mask == 0) return 0;
    const __m256d det = _mm256_add_pd(_mm256_add_pd(u, v), w);
    const __m256d sz = _mm256_cvtps_pd(r.sz);
    const __m256d t_scaled =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(u, _mm256_mul_pd(sz, _mm256_cvtps_pd(az))),
                                    _mm256_mul_pd(v, _mm256_mul_pd(sz, _mm256_cvtps_pd(bz)))),
                      _mm256_mul_pd(w, _mm256_mul_pd(sz, _mm256_cvtps_pd(cz))));
    const __m256d inv_det = _mm256_div_pd(_mm256_set1_pd(1.0), det);
    const __m128 t = _mm256_cvtpd_ps(_mm256_mul_pd(t_scaled, inv_det));
    // det = 0 (zero-area triangles, unused lanes) gives an infinite or NaN t: rejected.
    const __m128 in_range = _mm_and_ps(_mm_cmpgt_ps(t, _mm_set1_ps(tmin)), _mm_cmplt_ps(t, _mm_set1_ps(tmax)));
    mask &= _mm_movemask_ps(in_range) & ~_mm256_movemask_pd(_mm256_cmp_pd(det, zero, _CMP_EQ_OQ));
    if (mask == 0) return 0;
    _mm_storeu_ps(t_out, t);
    _mm_storeu_ps(u_out, _mm256_cvtpd_ps(_mm256_mul_pd(v, inv_det)));
    _mm_storeu_ps(v_out, _mm256_cvtpd_ps(_mm256_mul_pd(w, inv_det)));
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

template <bool AnyHit, typename Filter>
bool TriangleBvh::intersect(Ray& ray, Hit& hit, Filter&& accept) const {
    constexpr bool kFiltered = !std::is_same_v<std::decay_t<Filter>, AcceptAllHits>;
    const detail::BlockRay block_ray(ray);
    return wide_.traverse<AnyHit>(ray, [&](uint32_t leaf, Ray& r) {
        const TriangleBlock& block = blocks_[leaf];
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
    });
}

}  // namespace glint
