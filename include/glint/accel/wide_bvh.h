#pragma once
/// \file An 8-wide BVH over abstract primitives, traversed one ray at a time with all eight
/// child boxes tested in one go (AVX2 when the compiler targets it).
///
/// Built by collapsing a binary SAH tree (build_binary_bvh): each wide node repeatedly opens
/// its largest-area inner child until it has eight children (Wald et al. 2008, "Getting Rid
/// of Packets"; Embree's BVH8 collapse works the same way). Like `Bvh`, it never sees a
/// shape: leaves are numbered, and the caller's callback intersects leaf k.

#include "glint/accel/sah_builder.h"
#include "glint/accel/traversal_count.h"
#include "glint/math/bounds3.h"
#include "glint/math/ray.h"

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace glint {

/// Eight child boxes as structure of arrays (lo_x, hi_x, lo_y, hi_y, lo_z, hi_z), 224 bytes.
/// A child is an inner node index, or kLeafBit | leaf index. Unused slots hold an empty box
/// (lo = +inf, hi = -inf), which no ray can enter.
struct alignas(32) WideNode {
    static constexpr uint32_t kWidth = 8;
    static constexpr uint32_t kLeafBit = 0x80000000u;
    float planes[6][kWidth];
    uint32_t child[kWidth];
};
static_assert(sizeof(WideNode) == 224);

/// A leaf: `count` entries of primitive_order() starting at `first`.
struct WideLeaf {
    uint32_t first = 0;
    uint32_t count = 0;
};

/// Per-ray constants of the slab test: the reciprocal direction (no NaN for axis-parallel
/// rays) and which of each node's planes is the near one, chosen by the direction's sign
/// so that the test needs no min/max per axis (Williams et al. 2005).
struct WideRay {
    Vec3 inv_dir, origin_inv_dir;
    uint32_t near_plane[3];
    /// Precomputes the constants for `ray`.
    explicit WideRay(const Ray& ray);
};

/// Default for WideBvh::traverse: leaves whose data is not worth prefetching.
struct NoLeafPrefetch {
    constexpr void operator()(uint32_t) const {}
};

/// Starts loading into L1 the cache lines of an object of `Bytes` bytes at `p`, which is
/// aligned to 32 bytes (so Bytes / 64 + 1 lines at most; one prefetch per line).
template <std::size_t Bytes>
inline void prefetch_lines(const void* p) {
    const char* c = static_cast<const char*>(p);
    [&]<std::size_t... I>(std::index_sequence<I...>) { (__builtin_prefetch(c + 64 * I, 0, 3), ...); }
    (std::make_index_sequence<(Bytes + 63) / 64>{});
}

class WideBvh {
public:
    /// Builds the binary tree with `config` (in the caller's TBB arena) and collapses it.
    void build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config = {});

    /// Visit leaves; `intersect_leaf(uint32_t leaf, Ray& ray) -> bool` tests a leaf's
    /// primitives, shrinks ray.tmax on a closer hit and returns true on a hit. Closest-hit
    /// traversal visits children front to back and skips subtrees behind ray.tmax; with
    /// AnyHit it stops at the first hit and does not sort. Returns whether anything was hit.
    /// `prefetch_leaf(uint32_t leaf)` may start loading a leaf's data when its box is hit.
    template <bool AnyHit, typename IntersectLeaf, typename PrefetchLeaf = NoLeafPrefetch,
              typename Count = NoTraversalCount>
    bool traverse(Ray& ray, IntersectLeaf&& intersect_leaf, PrefetchLeaf&& prefetch_leaf = {},
                  const Count& count = {}) const;

    /// Node 0 is the root; empty when there is nothing to hit.
    [[nodiscard]] std::span<const WideNode> nodes() const { return nodes_; }
    /// Leaf k's primitives, in the order traversal meets the leaves.
    [[nodiscard]] std::span<const WideLeaf> leaves() const { return leaves_; }
    /// Leaf entries in traversal order, mapping to the caller's primitive indices.
    [[nodiscard]] std::span<const uint32_t> primitive_order() const { return order_; }
    /// Box of all primitives.
    [[nodiscard]] Bounds3 bounds() const { return bounds_; }
    /// For callers that copied their primitives into leaf order: replaces every leaf index
    /// in the nodes by `leaf_payload(leaf) -> uint32_t` (below 2^31), which traverse() then
    /// hands to the leaf callback instead, and frees leaves() and primitive_order().
    template <typename LeafPayload>
    void encode_leaves(LeafPayload&& leaf_payload);
    /// Bytes of nodes, leaf ranges and primitive order.
    [[nodiscard]] std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(WideNode) + leaves_.size() * sizeof(WideLeaf) + order_.size() * sizeof(uint32_t);
    }

private:
    /// Slab test of the eight children; returns the hit mask and, with StoreEnter, writes
    /// their entry distances (shadow rays do not sort, so they skip the store).
    template <bool StoreEnter>
    [[nodiscard]] static uint32_t intersect_node(const WideNode& node, const WideRay& r, float tmin, float tmax,
                                                 float* t_enter);

    std::vector<WideNode> nodes_;
    std::vector<WideLeaf> leaves_;
    std::vector<uint32_t> order_;
    Bounds3 bounds_;
};

template <typename LeafPayload>
void WideBvh::encode_leaves(LeafPayload&& leaf_payload) {
    for (WideNode& node : nodes_)
        for (uint32_t& child : node.child)
            if (child & WideNode::kLeafBit) child = WideNode::kLeafBit | leaf_payload(child & ~WideNode::kLeafBit);
    leaves_ = {};
    order_ = {};
}

inline WideRay::WideRay(const Ray& ray) {
    for (int a = 0; a < 3; ++a) {
        // Tiny components become ±1e-30 so that the reciprocal stays finite and
        // (plane - origin) · inv_dir is never 0 · inf.
        float d = ray.direction[a];
        if (std::abs(d) < 1e-30f) d = std::copysign(1e-30f, d);
        inv_dir[a] = 1.0f / d;
        origin_inv_dir[a] = ray.origin[a] * inv_dir[a];
        near_plane[a] = 2 * a + (inv_dir[a] < 0.0f ? 1 : 0);
    }
}

/// Boxes are entered up to tmax·(1 + 2^-21) so that rounding in the slab test never culls
/// a box a watertight triangle test would hit (Woop, Benthin, Wald 2013, §3.3: robust BVH
/// traversal needs conservative box tests).
inline constexpr float kWideBoxSlack = 1.0f + 0x1p-21f;

template <bool StoreEnter>
inline uint32_t WideBvh::intersect_node(const WideNode& node, const WideRay& r, float tmin, float tmax,
                                        float* t_enter) {
#if defined(__AVX2__)
    auto plane_t = [&](int axis, uint32_t plane) {
        return _mm256_fmsub_ps(_mm256_load_ps(node.planes[plane]), _mm256_set1_ps(r.inv_dir[axis]),
                               _mm256_set1_ps(r.origin_inv_dir[axis]));
    };
    const __m256 near_x = plane_t(0, r.near_plane[0]), far_x = plane_t(0, r.near_plane[0] ^ 1);
    const __m256 near_y = plane_t(1, r.near_plane[1]), far_y = plane_t(1, r.near_plane[1] ^ 1);
    const __m256 near_z = plane_t(2, r.near_plane[2]), far_z = plane_t(2, r.near_plane[2] ^ 1);
    const __m256 enter = _mm256_max_ps(_mm256_max_ps(near_x, near_y), _mm256_max_ps(near_z, _mm256_set1_ps(tmin)));
    const __m256 exit = _mm256_min_ps(_mm256_min_ps(far_x, far_y), _mm256_min_ps(far_z, _mm256_set1_ps(tmax)));
    if constexpr (StoreEnter) _mm256_storeu_ps(t_enter, enter);
    const __m256 hit = _mm256_cmp_ps(enter, _mm256_mul_ps(exit, _mm256_set1_ps(kWideBoxSlack)), _CMP_LE_OQ);
    return static_cast<uint32_t>(_mm256_movemask_ps(hit));
#else
    uint32_t mask = 0;
    for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
        float enter = tmin, exit = tmax;
        for (int a = 0; a < 3; ++a) {
            const float t_near = node.planes[r.near_plane[a]][i] * r.inv_dir[a] - r.origin_inv_dir[a];
            const float t_far = node.planes[r.near_plane[a] ^ 1][i] * r.inv_dir[a] - r.origin_inv_dir[a];
            enter = t_near > enter ? t_near : enter;
            exit = t_far < exit ? t_far : exit;
        }
        if constexpr (StoreEnter) t_enter[i] = enter;
        if (enter <= exit * kWideBoxSlack) mask |= 1u << i;
    }
    return mask;
#endif
}

template <bool AnyHit, typename IntersectLeaf, typename PrefetchLeaf, typename Count>
bool WideBvh::traverse(Ray& ray, IntersectLeaf&& intersect_leaf, PrefetchLeaf&& prefetch_leaf,
                       const Count& count) const {
    if (nodes_.empty()) return false;
    const WideRay r(ray);
    const WideNode* const nodes = nodes_.data();
    struct Entry {
        uint32_t ref;
        float t_enter;
    };
    // Each wide level leaves at most seven entries behind, and a wide tree is no deeper
    // than the binary one it collapses.
    constexpr int kStackSize = 640;
    static_assert(kStackSize >= 7 * kMaxBinaryBvhDepth + 1);
    Entry stack[kStackSize];
    int top = 0;
    stack[top++] = {0, ray.tmin};
    bool hit = false;
    alignas(32) float t_enter[WideNode::kWidth];
    while (top > 0) {
        const Entry entry = stack[--top];
        if (!AnyHit && entry.t_enter > ray.tmax) continue;  // behind a hit found since the push
        uint32_t ref = entry.ref;
        bool reached_leaf = true;
        while (!(ref & WideNode::kLeafBit)) {
            const WideNode& node = nodes[ref];
            count.node();
            uint32_t mask = intersect_node<!AnyHit>(node, r, ray.tmin, ray.tmax, t_enter);
            if (mask == 0) {
                reached_leaf = false;
                break;
            }
            uint32_t first = static_cast<uint32_t>(std::countr_zero(mask));
            mask &= mask - 1;
            if (mask == 0) {
                ref = node.child[first];
                continue;
            }
            if constexpr (AnyHit) {
                // Shadow rays: any order will do, so skip the sorting.
                for (; mask; mask &= mask - 1) {
                    const auto i = static_cast<uint32_t>(std::countr_zero(mask));
                    stack[top++] = {node.child[i], 0.0f};
                }
                ref = node.child[first];
                continue;
            }
            // Several children hit: ask for all their cache lines now, so that the misses of
            // those visited later overlap with the work on the nearest one (as Embree does;
            // measured: it pays for closest-hit rays, not for shadow rays).
            for (uint32_t m = mask | (1u << first); m; m &= m - 1) {
                const uint32_t c = node.child[std::countr_zero(m)];
                if (c & WideNode::kLeafBit)
                    prefetch_leaf(c & ~WideNode::kLeafBit);
                else
                    prefetch_lines<sizeof(WideNode)>(&nodes[c]);
            }
            const auto second = static_cast<uint32_t>(std::countr_zero(mask));
            mask &= mask - 1;
            if (mask == 0) {
                // The common case of two hit children: push the far one, descend the near one.
                const bool swap = t_enter[second] < t_enter[first];
                const uint32_t near = swap ? second : first, far = swap ? first : second;
                stack[top++] = {node.child[far], t_enter[far]};
                ref = node.child[near];
                continue;
            }
            // Three or more: push all, insertion-sort them far to near, pop the nearest.
            const int base = top;
            stack[top++] = {node.child[first], t_enter[first]};
            stack[top++] = {node.child[second], t_enter[second]};
            for (; mask; mask &= mask - 1) {
                const auto i = static_cast<uint32_t>(std::countr_zero(mask));
                stack[top++] = {node.child[i], t_enter[i]};
            }
            for (int i = base + 1; i < top; ++i) {
                const Entry e = stack[i];
                int j = i - 1;
                for (; j >= base && stack[j].t_enter < e.t_enter; --j) stack[j + 1] = stack[j];
                stack[j + 1] = e;
            }
            ref = stack[--top].ref;
        }
        if (!reached_leaf) continue;
        if (intersect_leaf(ref & ~WideNode::kLeafBit, ray)) {
            hit = true;
            if constexpr (AnyHit) return true;
        }
    }
    return hit;
}

}  // namespace glint
