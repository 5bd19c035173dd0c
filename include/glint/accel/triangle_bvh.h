#pragma once
/// \file The bottom-level structure of a triangle mesh: an 8-wide BVH whose leaves hold up
/// to four triangles (one block), copied in leaf order and tested together with SSE
/// (x86-64; other targets test them one by one with the scalar watertight test), or two
/// blocks' eight with AVX where an any-hit ray meets both leaves in one node
/// (accel/triangle_block_test.h).
///
/// One block per leaf was measured on the shared meshes: leaves of two or four blocks save
/// 10% memory but cost up to 15% on incoherent rays.
///
/// Copying the vertices (36 bytes per triangle, plus the index) into the leaves costs
/// memory but saves the index indirection and its cache misses on every leaf visit; the
/// SAH counts leaf cost in blocks of four, so few slots are wasted (Embree's Triangle4
/// leaves store more: the edges and the normal as well).

#include "glint/accel/ray_packet.h"
#include "glint/accel/triangle_block_test.h"
#include "glint/accel/wide_bvh.h"
#include "glint/geometry/hit.h"
#include "glint/geometry/triangle.h"
#include "glint/util/huge_page_array.h"

#include <span>
#include <type_traits>

namespace glint {

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
/// One callable of several lambdas: the leaf callback that takes one leaf or two.
template <typename... F>
struct Overloaded : F... {
    using F::operator()...;
};
}  // namespace detail

template <bool AnyHit, typename Filter, typename Count>
bool TriangleBvh::intersect(Ray& ray, Hit& hit, Filter&& accept, const Count& count) const {
    constexpr bool kFiltered = !std::is_same_v<std::decay_t<Filter>, AcceptAllHits>;
    const detail::BlockRay block_ray(ray);
    auto count_block = [&](const TriangleBlock& block) {
        if constexpr (!std::is_same_v<Count, NoTraversalCount>) {
            uint64_t real = 0;  // padding lanes hold kNoHit
            for (const uint32_t triangle : block.triangle) real += triangle != kNoHit;
            count.primitives(real);
        }
    };
    // Of the lanes in `mask`, takes the nearest that the filter accepts (any accepted lane for
    // AnyHit); `triangle(lane)` names a lane's triangle.
    auto take = [&](uint32_t mask, const float* t, const float* u, const float* v, auto&& triangle, Ray& r) {
        while (mask) {
            auto best = static_cast<uint32_t>(std::countr_zero(mask));
            if constexpr (!AnyHit)
                for (uint32_t m = mask & (mask - 1); m; m &= m - 1) {
                    const auto i = static_cast<uint32_t>(std::countr_zero(m));
                    if (t[i] < t[best]) best = i;
                }
            if constexpr (kFiltered) {
                if (!accept(triangle(best), u[best], v[best])) {
                    mask &= ~(1u << best);
                    continue;
                }
            }
            r.tmax = t[best];
            hit.t = t[best];
            hit.primitive = triangle(best);
            hit.u = u[best];
            hit.v = v[best];
            return true;
        }
        return false;
    };
    auto intersect_leaf = [&](uint32_t leaf, Ray& r) {
        const TriangleBlock& block = blocks_[leaf];
        count_block(block);
        float t[4], u[4], v[4];
        const uint32_t mask = detail::intersect_block(block, block_ray, r.tmin, r.tmax, t, u, v);
        return take(
            mask, t, u, v, [&](uint32_t lane) { return block.triangle[lane]; }, r);
    };
#if defined(__AVX__)
    if constexpr (AnyHit) {
        const detail::LaneRay<detail::EightLanes> pair_ray(block_ray);  // one set-up for both widths
        auto intersect_pair = [&](uint32_t leaf, uint32_t other_leaf, Ray& r) {
            const TriangleBlock& a = blocks_[leaf];
            const TriangleBlock& b = blocks_[other_leaf];
            count_block(a);
            count_block(b);
            float t[8], u[8], v[8];
            const uint32_t mask = detail::intersect_block_pair(a, b, pair_ray, r.tmin, r.tmax, t, u, v);
            return take(
                mask, t, u, v, [&](uint32_t lane) { return lane < 4 ? a.triangle[lane] : b.triangle[lane - 4]; }, r);
        };
        detail::Overloaded<decltype(intersect_leaf), decltype(intersect_pair)> leaves{intersect_leaf, intersect_pair};
        return wide_.traverse<AnyHit>(ray, leaves, count);
    }
#endif
    return wide_.traverse<AnyHit>(ray, intersect_leaf, count);
}

}  // namespace glint
