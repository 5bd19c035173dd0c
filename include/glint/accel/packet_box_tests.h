#pragma once
/// \file Box tests for a RayPacket against a WideNode's children (AVX2): the per-lane slab
/// test, with each lane's arithmetic exactly the single-ray test's (the near plane chosen per
/// lane by the sign of its direction, Williams et al. 2005), and a conservative test of all
/// eight children for the whole packet at once (the packet's frustum). Used by
/// wide_packet_traversal.h.

#if defined(__AVX2__)

#include "glint/accel/ray_packet.h"
#include "glint/accel/wide_bvh.h"

#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

namespace glint::detail {

/// The slab test's per-lane constants for a packet, as WideRay computes them per ray.
struct PacketSlabRay {
    __m256 inv_dir[3], origin_inv_dir[3];
    /// All bits set in the lanes whose direction component is negative: there the hi plane
    /// is the near one.
    __m256 negative[3];
    __m256 tmin;
    /// WideRay::order_shift of the packet's first active ray: the children are taken in
    /// that ray's front-to-back order (coherent rays share their octant).
    uint32_t order_shift;
    /// Whether all active rays head into the same octant.
    bool shared_octant = true;

    /// The same arithmetic as WideRay's, eight lanes at a time.
    explicit PacketSlabRay(const RayPacket& packet) {
        const __m256 sign = _mm256_set1_ps(-0.0f), tiny = _mm256_set1_ps(1e-30f);
        const auto active = static_cast<int>(packet.active);
        uint32_t octant = 0;
        for (int a = 0; a < 3; ++a) {
            __m256 d = _mm256_load_ps(packet.direction[a]);
            const __m256 is_tiny = _mm256_cmp_ps(_mm256_andnot_ps(sign, d), tiny, _CMP_LT_OQ);
            d = _mm256_blendv_ps(d, _mm256_or_ps(_mm256_and_ps(d, sign), tiny), is_tiny);
            inv_dir[a] = _mm256_div_ps(_mm256_set1_ps(1.0f), d);
            origin_inv_dir[a] = _mm256_mul_ps(_mm256_load_ps(packet.origin[a]), inv_dir[a]);
            negative[a] = _mm256_cmp_ps(inv_dir[a], _mm256_setzero_ps(), _CMP_LT_OQ);
            const int negative_lanes = _mm256_movemask_ps(negative[a]) & active;
            if (negative_lanes != 0 && negative_lanes != active) shared_octant = false;
            if (negative_lanes & active & -active) octant |= 1u << a;  // the first active lane's sign
        }
        order_shift = 3 * octant;
        tmin = _mm256_load_ps(packet.tmin);
    }
};

/// The smallest and the largest of the eight lanes, in every lane.
inline __m256 horizontal_min(__m256 v) {
    v = _mm256_min_ps(v, _mm256_permute2f128_ps(v, v, 1));
    v = _mm256_min_ps(v, _mm256_permute_ps(v, 0b01001110));
    return _mm256_min_ps(v, _mm256_permute_ps(v, 0b10110001));
}
inline __m256 horizontal_max(__m256 v) {
    v = _mm256_max_ps(v, _mm256_permute2f128_ps(v, v, 1));
    v = _mm256_max_ps(v, _mm256_permute_ps(v, 0b01001110));
    return _mm256_max_ps(v, _mm256_permute_ps(v, 0b10110001));
}

/// The lanes of `lanes` as a vector mask.
inline __m256 lane_vector(uint32_t lanes) {
    const __m256i bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    return _mm256_castsi256_ps(
        _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(lanes)), bits), bits));
}

/// Slab test of child `slot` against the packet: returns where each lane enters the box,
/// NaN in the lanes that miss it or are not in `lanes` (a lane mask vector), and sets
/// `mask` to the lanes that enter. NaN, not +inf, so that no comparison with a lane's
/// tmax (+inf for an unbounded ray) lets it in.
inline __m256 packet_slab_test(const WideNode& node, uint32_t slot, const PacketSlabRay& r, __m256 tmax,
                               __m256 lanes, uint32_t& mask) {
    auto plane_t = [&](int axis, bool near) {
        const __m256 lo = _mm256_broadcast_ss(&node.planes[2 * axis][slot]);
        const __m256 hi = _mm256_broadcast_ss(&node.planes[2 * axis + 1][slot]);
        const __m256 plane = near ? _mm256_blendv_ps(lo, hi, r.negative[axis]) : _mm256_blendv_ps(hi, lo, r.negative[axis]);
        return _mm256_fmsub_ps(plane, r.inv_dir[axis], r.origin_inv_dir[axis]);
    };
    const __m256i enter =
        _mm256_max_epi32(_mm256_max_epi32(distance_order(plane_t(0, true)), distance_order(plane_t(1, true))),
                         _mm256_max_epi32(distance_order(plane_t(2, true)), distance_order(r.tmin)));
    const __m256i exit =
        _mm256_min_epi32(_mm256_min_epi32(distance_order(plane_t(0, false)), distance_order(plane_t(1, false))),
                         _mm256_min_epi32(distance_order(plane_t(2, false)), distance_order(tmax)));
    const __m256 hit = _mm256_and_ps(entered_within_slack(enter, exit), lanes);
    mask = static_cast<uint32_t>(_mm256_movemask_ps(hit));
    return _mm256_blendv_ps(_mm256_set1_ps(std::numeric_limits<float>::quiet_NaN()), _mm256_castsi256_ps(enter), hit);
}

/// One box test for the whole packet (Reshetov et al. 2005, "Multi-Level Ray Tracing
/// Algorithm"; Embree's coherent mode): interval bounds, over the packet's rays, of where
/// they enter and leave each axis's slab. Needs one direction octant for all rays, so that
/// the near plane is the same for all.
///
/// For an axis with positive direction, ray r enters at (lo - o_r)·inv_r: its smallest value
/// over the packet is at the largest origin, min((lo - o_max)·inv_min, (lo - o_max)·inv_max)
/// whatever the sign of lo - o_max, and it leaves at most at the larger of
/// (hi - o_min)·inv_min and (hi - o_min)·inv_max; with negative direction hi and lo trade
/// places, as do o_min and o_max. Each bound is then widened by a relative and an absolute
/// margin larger than the rounding of both this test and the single-ray test, so the packet
/// visits every box any of its rays would visit alone (the culling is conservative; the
/// leaves still test each lane exactly).
struct PacketFrustum {
    /// Per axis: the near and far planes' indices, the origin bound each subtracts, the
    /// reciprocal direction's range and the absolute margin.
    uint32_t near_plane[3], far_plane[3];
    __m256 origin_near[3], origin_far[3], inv_min[3], inv_max[3], margin[3];
    __m256 tmin;
    uint32_t order_shift;
    static constexpr float kRelativeMargin = 0x1p-18f;

    PacketFrustum(const RayPacket& packet, const PacketSlabRay& r) : order_shift(r.order_shift) {
        const __m256 active = lane_vector(packet.active);
        const __m256 infinity = _mm256_set1_ps(kInfinity), minus_infinity = _mm256_set1_ps(-kInfinity);
        auto lowest = [&](__m256 v) { return horizontal_min(_mm256_blendv_ps(infinity, v, active)); };
        auto highest = [&](__m256 v) { return horizontal_max(_mm256_blendv_ps(minus_infinity, v, active)); };
        const uint32_t octant = order_shift / 3;
        for (int a = 0; a < 3; ++a) {
            const bool negative = (octant >> a & 1) != 0;
            near_plane[a] = 2 * a + (negative ? 1 : 0);
            far_plane[a] = near_plane[a] ^ 1;
            const __m256 origin = _mm256_load_ps(packet.origin[a]);
            const __m256 lo_origin = lowest(origin), hi_origin = highest(origin);
            origin_near[a] = negative ? lo_origin : hi_origin;
            origin_far[a] = negative ? hi_origin : lo_origin;
            inv_min[a] = lowest(r.inv_dir[a]);
            inv_max[a] = highest(r.inv_dir[a]);
            // The single-ray test rounds origin·inv: an error that scales with it, not with t.
            margin[a] = _mm256_mul_ps(highest(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), r.origin_inv_dir[a])),
                                      _mm256_set1_ps(kRelativeMargin));
        }
        tmin = lowest(r.tmin);
    }

    /// The eight children's boxes: the slots some ray may enter within [tmin, tmax_bound]
    /// (lanes of the result) and a lower bound of where (in `enter`).
    [[nodiscard]] __m256 test(const WideNode& node, __m256 tmax_bound, __m256& enter) const {
        const __m256 relative = _mm256_set1_ps(kRelativeMargin);
        const __m256 sign = _mm256_set1_ps(-0.0f);
        __m256 lower = tmin, upper = tmax_bound;
        for (int a = 0; a < 3; ++a) {
            const __m256 d_near = _mm256_sub_ps(_mm256_load_ps(node.planes[near_plane[a]]), origin_near[a]);
            const __m256 d_far = _mm256_sub_ps(_mm256_load_ps(node.planes[far_plane[a]]), origin_far[a]);
            const __m256 t_near = _mm256_min_ps(_mm256_mul_ps(d_near, inv_min[a]), _mm256_mul_ps(d_near, inv_max[a]));
            const __m256 t_far = _mm256_max_ps(_mm256_mul_ps(d_far, inv_min[a]), _mm256_mul_ps(d_far, inv_max[a]));
            lower = _mm256_max_ps(
                _mm256_sub_ps(_mm256_fnmadd_ps(_mm256_andnot_ps(sign, t_near), relative, t_near), margin[a]), lower);
            upper = _mm256_min_ps(
                _mm256_add_ps(_mm256_fmadd_ps(_mm256_andnot_ps(sign, t_far), relative, t_far), margin[a]), upper);
        }
        enter = lower;
        const __m256 used = _mm256_cmp_ps(_mm256_load_ps(node.planes[0]), _mm256_load_ps(node.planes[1]), _CMP_LE_OQ);
        return _mm256_and_ps(_mm256_cmp_ps(lower, upper, _CMP_LE_OQ), used);
    }
};

/// The largest tmax among `lanes`: no ray of the packet reaches a box entered beyond it.
inline float largest_tmax(const RayPacket& packet, uint32_t lanes) {
    float largest = -kInfinity;
    for (; lanes; lanes &= lanes - 1) largest = std::max(largest, packet.tmax[std::countr_zero(lanes)]);
    return largest;
}

}  // namespace glint::detail

#endif
