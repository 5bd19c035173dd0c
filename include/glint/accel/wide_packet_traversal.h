#pragma once
/// \file Packet traversal of the 8-wide BVH: a RayPacket's eight rays go down the tree
/// together, so that a node is fetched and the stack worked once for all of them, which is
/// where coherent rays gain (Wald et al. 2001, "Interactive Rendering with Coherent Ray
/// Tracing"). A subtree is entered with the lanes that enter its box, by the same
/// arithmetic as the single-ray test (packet_box_tests.h), so each lane visits the leaves
/// that its ray would visit alone and finds the same hit.
///
/// Two ways down, chosen per packet:
/// - rays sharing a direction octant (camera rays, shadow rays toward one light) test a node's
///   eight children against the packet's frustum first, in one go, and only the children it
///   may enter lane by lane (Reshetov et al. 2005; Embree's coherent mode);
/// - the others test every child lane by lane, SIMD across the rays.

#if defined(__AVX2__)

#include "glint/accel/packet_box_tests.h"
#include "glint/accel/ray_packet.h"
#include "glint/accel/wide_bvh.h"

#include <immintrin.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <span>

namespace glint {

namespace detail {

/// The general packet traversal: every lane tested against every child box; a subtree is
/// entered with the lanes that enter its box.
template <bool AnyHit, typename IntersectLeaf>
uint32_t traverse_packet_lanes(std::span<const WideNode> nodes, RayPacket& packet, const PacketSlabRay& r,
                               IntersectLeaf&& intersect_leaf) {
    const __m256 not_entered = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
    // A stack entry keeps each lane's entry distance into the subtree, NaN for lanes that
    // do not enter it; a lane takes part while that distance is within its tmax.
    struct alignas(32) Entry {
        __m256 enter;
        uint32_t ref;
    };
    Entry stack[kWideStackSize];
    int top = 0;
    stack[top++] = {_mm256_blendv_ps(not_entered, r.tmin, lane_vector(packet.active)), 0};
    // AnyHit: a lane that has hit gets tmax = -inf, which no box test passes.
    __m256 tmax = _mm256_load_ps(packet.tmax);
    uint32_t hit_lanes = 0;
    uint32_t child[WideNode::kWidth];
    __m256 child_enter[WideNode::kWidth];
    while (top > 0) {
        const Entry entry = stack[--top];
        __m256 enter = entry.enter;
        uint32_t ref = entry.ref;
        bool reached_leaf = true;
        while (!(ref & WideNode::kLeafBit)) {
            const WideNode& node = nodes[ref];
            const __m256 lanes = _mm256_cmp_ps(enter, tmax, _CMP_LE_OQ);
            if (_mm256_movemask_ps(lanes) == 0) {
                reached_leaf = false;
                break;
            }
            // The children hit by any lane, in the packet's front-to-back order.
            uint32_t hit_count = 0;
            for (uint32_t k = 0; k < WideNode::kWidth; ++k) {
                const uint32_t slot = (node.order[k] >> r.order_shift) & 7;
                if (!(node.planes[0][slot] <= node.planes[1][slot])) continue;  // unused slot
                uint32_t entered;
                const __m256 e = detail::packet_slab_test(node, slot, r, tmax, lanes, entered);
                if (entered == 0) continue;
                child[hit_count] = node.child[slot];
                child_enter[hit_count++] = e;
            }
            if (hit_count == 0) {
                reached_leaf = false;
                break;
            }
            // Push the others far to near, descend into the nearest.
            for (uint32_t k = hit_count - 1; k > 0; --k) stack[top++] = {child_enter[k], child[k]};
            ref = child[0];
            enter = child_enter[0];
        }
        if (!reached_leaf) continue;
        const auto lanes = static_cast<uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(enter, tmax, _CMP_LE_OQ)));
        if (lanes == 0) continue;
        const uint32_t hits = intersect_leaf(ref & ~WideNode::kLeafBit, packet, lanes);
        hit_lanes |= hits;
        if constexpr (AnyHit) {
            if (hit_lanes == packet.active) return hit_lanes;
            tmax = _mm256_blendv_ps(tmax, _mm256_set1_ps(-kInfinity), lane_vector(hits));
        } else {
            tmax = _mm256_load_ps(packet.tmax);
        }
    }
    return hit_lanes;
}

/// Frustum traversal: one test of a node's eight children for the whole packet, then each
/// child it lets through tested lane by lane (the exact single-ray test) and entered with the
/// lanes that enter it. The frustum alone would be loose where the rays start apart (shadow
/// rays from points spread over a surface); the lane tests keep every subtree and leaf to the
/// rays that reach it.
template <bool AnyHit, typename IntersectLeaf>
uint32_t traverse_packet_frustum(std::span<const WideNode> nodes, RayPacket& packet, const PacketSlabRay& r,
                                 const PacketFrustum& frustum, IntersectLeaf&& intersect_leaf) {
    struct Entry {
        uint32_t ref;
        float enter;
        uint32_t lanes;  ///< the lanes that enter its box
    };
    Entry stack[kWideStackSize];
    int top = 0;
    uint32_t live = packet.active, hit_lanes = 0;
    stack[top++] = {0, -kInfinity, live};
    float tmax_bound = largest_tmax(packet, live);
    alignas(32) float t_enter[WideNode::kWidth];
    alignas(32) uint32_t child[WideNode::kWidth];
    Entry near_to_far[WideNode::kWidth];
    const __m256i shift = _mm256_set1_epi32(static_cast<int>(frustum.order_shift));
    while (top > 0) {
        const Entry entry = stack[--top];
        if (entry.enter > tmax_bound) continue;
        uint32_t ref = entry.ref, lanes = entry.lanes;
        bool reached_leaf = true;
        while (!(ref & WideNode::kLeafBit)) {
            const WideNode& node = nodes[ref];
            __m256 enter;
            const __m256 hit = frustum.test(node, _mm256_set1_ps(tmax_bound * kWideBoxSlackFactor), enter);
            // Closest hits take the children near to far by the octant's order; any-hit
            // packets, like single any-hit rays, fare better in slot order (leaves first).
            __m256 hit_ordered = hit, enter_ordered = enter;
            __m256i child_ordered = _mm256_load_si256(reinterpret_cast<const __m256i*>(node.child));
            if constexpr (!AnyHit) {
                const __m256i order = _mm256_and_si256(
                    _mm256_srlv_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.order)), shift),
                    _mm256_set1_epi32(7));
                hit_ordered = _mm256_permutevar8x32_ps(hit, order);
                enter_ordered = _mm256_permutevar8x32_ps(enter, order);
                child_ordered = _mm256_permutevar8x32_epi32(child_ordered, order);
            }
            const auto mask = static_cast<uint32_t>(_mm256_movemask_ps(hit_ordered));
            _mm256_store_ps(t_enter, enter_ordered);
            _mm256_store_si256(reinterpret_cast<__m256i*>(child), child_ordered);
            uint32_t count = 0;
            if (mask != 0) {
                const __m256 tmax = _mm256_load_ps(packet.tmax), node_lanes = lane_vector(lanes & live);
                for (uint32_t m = mask; m; m &= m - 1) {
                    const auto k = static_cast<uint32_t>(std::countr_zero(m));
                    const uint32_t slot = AnyHit ? k : (node.order[k] >> frustum.order_shift) & 7;
                    uint32_t entered;
                    packet_slab_test(node, slot, r, tmax, node_lanes, entered);
                    if (entered != 0) near_to_far[count++] = {child[k], t_enter[k], entered};
                }
            }
            if (count == 0) {
                reached_leaf = false;
                break;
            }
            // Descend into the first, push the others: far to near (any-hit: the highest
            // slot to be taken next).
            if constexpr (AnyHit) {
                for (uint32_t k = 1; k < count; ++k) stack[top++] = near_to_far[k];
            } else {
                for (uint32_t k = count - 1; k > 0; --k) stack[top++] = near_to_far[k];
            }
            ref = near_to_far[0].ref;
            lanes = near_to_far[0].lanes;
        }
        if (!reached_leaf) continue;
        lanes &= live;
        if (lanes == 0) continue;
        const uint32_t hits = intersect_leaf(ref & ~WideNode::kLeafBit, packet, lanes);
        if (hits == 0) continue;
        hit_lanes |= hits;
        if constexpr (AnyHit) {
            live &= ~hits;
            if (live == 0) return hit_lanes;
        }
        tmax_bound = largest_tmax(packet, live);
    }
    return hit_lanes;
}

}  // namespace detail

/// Traverses `nodes` (a WideBvh's, leaves encoded or not) with the packet's active lanes.
/// `intersect_leaf(uint32_t leaf, RayPacket& packet, uint32_t lanes) -> uint32_t` tests a
/// leaf against the lanes in `lanes`, shrinks their tmax on closer hits and returns the
/// lanes it hit. Closest-hit traversal culls a subtree for the lanes whose tmax has moved
/// in front of its box; with AnyHit a lane stops at its first hit and the packet when all
/// have. Returns the lanes that hit anything.
///
/// Packets whose rays share a direction octant (camera rays, shadow rays toward a light
/// from nearby points) take the frustum traversal; the others test lane by lane.
template <bool AnyHit, typename IntersectLeaf>
uint32_t traverse_packet(std::span<const WideNode> nodes, RayPacket& packet, IntersectLeaf&& intersect_leaf) {
    if (nodes.empty() || packet.active == 0) return 0;
    const detail::PacketSlabRay r(packet);
    if (r.shared_octant) {
        const detail::PacketFrustum frustum(packet, r);
        return detail::traverse_packet_frustum<AnyHit>(nodes, packet, r, frustum, intersect_leaf);
    }
    return detail::traverse_packet_lanes<AnyHit>(nodes, packet, r, intersect_leaf);
}

}  // namespace glint

#endif
