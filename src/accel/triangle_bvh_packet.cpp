/// Packet queries of the mesh BVH: the watertight triangle test run for eight rays at once
/// against each triangle of a leaf block, under traverse_packet. Without AVX2 the lanes are
/// traced one by one.

#include "glint/accel/triangle_bvh.h"
#include "glint/accel/wide_packet_traversal.h"

#include <bit>

namespace glint {

#if defined(__AVX2__)

namespace {

/// WatertightRay for each lane: the permuted origin (roles x, y, z are the lane's kx, ky,
/// kz), the shear, and for each role whether its axis is 0 or 1 (else 2), as lane masks.
struct PacketWatertightRay {
    __m256 origin[3], shear[3];
    __m256 axis_is_0[3], axis_is_1[3];
    __m256 tmin;
    /// Whether all active lanes have the same kx, ky, kz (rays of a coherent packet
    /// nearly always do), and those of the first: then a vertex needs no per-lane selection.
    bool shared_axes = true;
    int axis[3] = {0, 1, 2};

    /// WatertightRay's choices and arithmetic, eight lanes at a time: kz is the axis of
    /// the largest |direction| component (max_axis's tie rules), kx and ky follow it
    /// cyclically.
    explicit PacketWatertightRay(const RayPacket& packet) {
        const __m256 sign = _mm256_set1_ps(-0.0f);
        const __m256 d[3] = {_mm256_load_ps(packet.direction[0]), _mm256_load_ps(packet.direction[1]),
                             _mm256_load_ps(packet.direction[2])};
        const __m256 ax = _mm256_andnot_ps(sign, d[0]), ay = _mm256_andnot_ps(sign, d[1]),
                     az = _mm256_andnot_ps(sign, d[2]);
        const __m256 x_over_y = _mm256_cmp_ps(ax, ay, _CMP_GT_OQ);
        const __m256 kz_is_0 = _mm256_and_ps(x_over_y, _mm256_cmp_ps(ax, az, _CMP_GT_OQ));
        const __m256 kz_is_1 = _mm256_andnot_ps(x_over_y, _mm256_cmp_ps(ay, az, _CMP_GT_OQ));
        const __m256 kz_is_2 = _mm256_andnot_ps(_mm256_or_ps(kz_is_0, kz_is_1), _mm256_castsi256_ps(_mm256_set1_epi32(-1)));
        axis_is_0[2] = kz_is_0;
        axis_is_1[2] = kz_is_1;
        // kx = kz + 1 and ky = kz + 2 (mod 3), WatertightRay's order.
        static_assert(WatertightRay::kNextAxis[0] == 1 && WatertightRay::kNextAxis[1] == 2 &&
                      WatertightRay::kNextAxis[2] == 0);
        axis_is_0[0] = kz_is_2;
        axis_is_1[0] = kz_is_0;
        axis_is_0[1] = kz_is_1;
        axis_is_1[1] = kz_is_2;
        shear[2] = _mm256_div_ps(_mm256_set1_ps(1.0f), pick_lanes(2, d));
        shear[0] = _mm256_mul_ps(pick_lanes(0, d), shear[2]);
        shear[1] = _mm256_mul_ps(pick_lanes(1, d), shear[2]);
        const __m256 o[3] = {_mm256_load_ps(packet.origin[0]), _mm256_load_ps(packet.origin[1]),
                             _mm256_load_ps(packet.origin[2])};
        for (int role = 0; role < 3; ++role) origin[role] = pick_lanes(role, o);
        tmin = _mm256_load_ps(packet.tmin);
        const auto active = static_cast<int>(packet.active);
        const int first = active & -active;
        for (int role = 0; role < 3; ++role) {
            const int is0 = _mm256_movemask_ps(axis_is_0[role]) & active;
            const int is1 = _mm256_movemask_ps(axis_is_1[role]) & active;
            if ((is0 != 0 && is0 != active) || (is1 != 0 && is1 != active)) shared_axes = false;
            axis[role] = (is0 & first) ? 0 : (is1 & first) ? 1 : 2;
        }
    }

    /// The component of `v` (one vector per axis) that plays `role` in each lane.
    [[nodiscard]] __m256 pick_lanes(int role, const __m256* v) const {
        return _mm256_blendv_ps(_mm256_blendv_ps(v[2], v[1], axis_is_1[role]), v[0], axis_is_0[role]);
    }

    /// The coordinate that plays `role` in each lane of the vertex whose x is at `p` (in a
    /// TriangleBlock, where its y and z follow at a stride of the block's width).
    template <bool SharedAxes>
    [[nodiscard]] __m256 pick(int role, const float* p) const {
        constexpr int kStride = TriangleBlock::kWidth;
        if constexpr (SharedAxes) return _mm256_broadcast_ss(&p[kStride * axis[role]]);
        return _mm256_blendv_ps(
            _mm256_blendv_ps(_mm256_broadcast_ss(&p[2 * kStride]), _mm256_broadcast_ss(&p[kStride]), axis_is_1[role]),
            _mm256_broadcast_ss(&p[0]), axis_is_0[role]);
    }
};

/// intersect_triangle_watertight of triangle `triangle` of `block` against the packet's eight
/// rays: the vertex sheared by each lane's ray, then the steps every SIMD form of the test
/// shares (detail::hit_sheared_lanes), so a ray gets the same bits here as alone. Returns the
/// lanes (rays) that hit within (tmin, tmax) and, through the out-parameters, t and the
/// barycentrics of vertices 1 and 2 for them. Inlined into the loop over a block's
/// triangles: called, its eight-lane results came back through memory and the packet's
/// constants were read through pointers (packets +2 to +16 %, docs/performance.md).
/// Closest-hit packets (camera rays) leave as soon as no ray is inside the triangle's edges;
/// any-hit packets (shadow rays from a surface) decide in one mask (hit_sheared_lanes says why).
template <bool AnyHit, bool SharedAxes>
[[gnu::always_inline]] inline uint32_t intersect_triangle_packet(const TriangleBlock& block, uint32_t triangle,
                                                                 const PacketWatertightRay& r, __m256 tmax,
                                                                 __m256& t_out, __m256& u_out, __m256& v_out) {
    detail::ShearedTriangle<detail::EightLanes> sheared;
    for (int k = 0; k < 3; ++k) {
        const float* p = &block.v[k][0][triangle];
        sheared.z[k] = _mm256_sub_ps(r.pick<SharedAxes>(2, p), r.origin[2]);
        sheared.x[k] =
            detail::minus_product(_mm256_sub_ps(r.pick<SharedAxes>(0, p), r.origin[0]), r.shear[0], sheared.z[k]);
        sheared.y[k] =
            detail::minus_product(_mm256_sub_ps(r.pick<SharedAxes>(1, p), r.origin[1]), r.shear[1], sheared.z[k]);
    }
    return detail::hit_sheared_lanes<detail::EightLanes, !AnyHit>(sheared, r.shear[2], r.tmin, tmax, t_out, u_out,
                                                                  v_out);
}

/// The block's triangles against the packet's `lanes`. Closest hit: each hit shrinks its
/// lane's tmax and is written to `hits`, so a later triangle must be nearer to count.
template <bool AnyHit, bool SharedAxes>
uint32_t intersect_block_packet(const TriangleBlock& block, const PacketWatertightRay& r, RayPacket& packet,
                                uint32_t lanes, PacketHits* hits) {
    uint32_t hit_lanes = 0;
    for (uint32_t lane = 0; lane < TriangleBlock::kWidth && block.triangle[lane] != kNoHit; ++lane) {
        __m256 t, u, v;
        const uint32_t hit =
            intersect_triangle_packet<AnyHit, SharedAxes>(block, lane, r, _mm256_load_ps(packet.tmax), t, u, v) & lanes;
        if (hit == 0) continue;
        hit_lanes |= hit;
        if constexpr (AnyHit) {
            lanes &= ~hit;
            if (lanes == 0) break;
        } else {
            const __m256i m = _mm256_castps_si256(detail::lane_vector(hit));
            _mm256_maskstore_ps(packet.tmax, m, t);
            _mm256_maskstore_ps(hits->t, m, t);
            _mm256_maskstore_ps(hits->u, m, u);
            _mm256_maskstore_ps(hits->v, m, v);
            _mm256_maskstore_epi32(reinterpret_cast<int*>(hits->primitive), m,
                                   _mm256_set1_epi32(static_cast<int>(block.triangle[lane])));
        }
    }
    return hit_lanes;
}

template <bool AnyHit>
uint32_t trace_packet(const WideBvh& bvh, std::span<const TriangleBlock> blocks, RayPacket& packet,
                      PacketHits* hits) {
    const PacketWatertightRay r(packet);
    if (r.shared_axes)
        return traverse_packet<AnyHit>(bvh.nodes(), packet, [&](uint32_t leaf, RayPacket& p, uint32_t lanes) {
            return intersect_block_packet<AnyHit, true>(blocks[leaf], r, p, lanes, hits);
        });
    return traverse_packet<AnyHit>(bvh.nodes(), packet, [&](uint32_t leaf, RayPacket& p, uint32_t lanes) {
        return intersect_block_packet<AnyHit, false>(blocks[leaf], r, p, lanes, hits);
    });
}

}  // namespace

uint32_t TriangleBvh::intersect_packet(RayPacket& packet, PacketHits& hits) const {
    return trace_packet<false>(wide_, blocks_, packet, &hits);
}

uint32_t TriangleBvh::occluded_packet(const RayPacket& packet) const {
    RayPacket scratch = packet;  // the traversal's leaves take it mutable, but AnyHit changes nothing
    return trace_packet<true>(wide_, blocks_, scratch, nullptr);
}

#else

uint32_t TriangleBvh::intersect_packet(RayPacket& packet, PacketHits& hits) const {
    return intersect_lane_by_lane(packet, hits, [&](Ray& ray, Hit& hit) { return intersect<false>(ray, hit); });
}

uint32_t TriangleBvh::occluded_packet(const RayPacket& packet) const {
    return occluded_lane_by_lane(packet, [&](const Ray& ray) {
        Ray r = ray;
        Hit scratch;
        return intersect<true>(r, scratch);
    });
}

#endif

}  // namespace glint
