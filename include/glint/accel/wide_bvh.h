#pragma once
/// \file An 8-wide BVH over abstract primitives, traversed one ray at a time with all eight
/// child boxes tested in one go (AVX2 when the compiler targets it).
///
/// Built by collapsing a binary SAH tree (build_binary_bvh) into the wide nodes whose summed
/// surface area, the expected number of node visits, is smallest: the dynamic program of
/// Ylitie, Karras and Laine 2017 over the binary nodes, with the binary tree's leaves kept.
/// (Opening each wide node's largest-area child until it has eight, as Wald et al. 2008 and
/// Embree do, leaves the nodes 54-56 % full on the Stanford meshes; this collapse fills them
/// 73-75 %, with 30 % fewer nodes.) It never sees a shape: leaves are
/// numbered, and the caller's callback intersects leaf k. Both of Glint's levels are one: the
/// scene's top level over objects and each triangle mesh's bottom level.

#include "glint/accel/sah_builder.h"
#include "glint/accel/traversal_count.h"
#include "glint/math/bounds3.h"
#include "glint/math/ray.h"
#include "glint/util/uninitialized_allocator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace glint {

/// Eight child boxes as structure of arrays (lo_x, hi_x, lo_y, hi_y, lo_z, hi_z), 256 bytes.
/// A child is an inner node index, or kLeafBit | leaf index. Unused slots hold an empty box
/// (lo = +inf, hi = -inf), which no ray can enter.
///
/// `order` is the front-to-back order of the children for each of the eight ray octants,
/// precomputed at build time so that traversal permutes instead of sorting (tinybvh's
/// BVH8_CPU `perm8`; the idea is the octant-ordered traversal of Garanzha and Loop 2010):
/// bits [3o, 3o + 3) of order[k] are the slot that comes k-th for a ray whose direction has
/// octant o (bit a of o set when the direction's component a is negative).
struct alignas(32) WideNode {
    static constexpr uint32_t kWidth = 8;
    static constexpr uint32_t kLeafBit = 0x80000000u;
    float planes[6][kWidth];
    uint32_t child[kWidth];
    uint32_t order[kWidth];
};
static_assert(sizeof(WideNode) == 256);

/// A WideBvh's nodes: sizing the array leaves them unwritten for the collapse, which writes
/// every byte of every node, in parallel.
using WideNodeArray = UninitializedArray<WideNode>;

/// Entries a traversal stack of a WideBvh needs: each wide level leaves at most seven
/// children behind, a wide tree is no deeper than the binary one it collapses, and a
/// compressed push may write a whole register of eight past the top.
inline constexpr int kWideStackSize = 7 * kMaxBinaryBvhDepth + WideNode::kWidth;

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
    /// 3 × the direction's octant: the shift that picks its child order from WideNode::order.
    uint32_t order_shift;
    /// Precomputes the constants for `ray`.
    explicit WideRay(const Ray& ray);
};

class WideBvh {
public:
    /// Builds the binary tree with `config` (in the caller's TBB arena) and collapses it.
    void build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config = {});
    /// The same over `count` primitives whose boxes `bounds` computes on demand.
    void build(uint32_t count, const PrimitiveBounds& bounds, const BvhBuildConfig& config = {});

    /// Visit leaves; `intersect_leaf(uint32_t leaf, Ray& ray) -> bool` tests a leaf's
    /// primitives, shrinks ray.tmax on a closer hit and returns true on a hit. Closest-hit
    /// traversal visits children front to back (in the order precomputed for the ray's
    /// octant) and skips subtrees behind ray.tmax; with AnyHit it stops at the first hit and
    /// takes a node's lowest hit slot first, then the others from the highest down (the
    /// collapse puts leaves in the low slots). Returns whether anything was hit. An any-hit
    /// callback that also takes `(uint32_t leaf, uint32_t other_leaf, Ray& ray) -> bool` gets
    /// a node's two lowest hit slots in one call when both are leaves (a mesh tests their
    /// triangles in one pass: docs/performance.md, "Two leaves in one test").
    template <bool AnyHit, typename IntersectLeaf, typename Count = NoTraversalCount>
    bool traverse(Ray& ray, IntersectLeaf&& intersect_leaf, const Count& count = {}) const;

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
    /// traverse<true>: the first hit in any order, children pushed without their distances.
    template <typename IntersectLeaf, typename Count>
    bool traverse_any_hit(Ray& ray, IntersectLeaf& intersect_leaf, const Count& count) const;
    /// The same test with the children in the ray octant's back-to-front order: bit j of the
    /// mask, child[j] and t_enter[j] are the (7 - j)-th child in its front-to-back order, so
    /// that pushing the hit lanes from the lowest up leaves the nearest on top of the stack.
    [[nodiscard]] static uint32_t intersect_node_far_to_near(const WideNode& node, const WideRay& r, float tmin,
                                                             float tmax, uint32_t* child, float* t_enter);

    // The nodes stay in ordinary memory: in huge pages the dragon's camera rays and packets
    // ran slower on one machine and the same on another (docs/performance.md, "The build's
    // page faults"), while the triangle blocks, three quarters of the bytes, gain from them
    // (huge_page_array.h).
    WideNodeArray nodes_;
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
    order_shift = 3 * ((near_plane[0] & 1) | (near_plane[1] & 1) << 1 | (near_plane[2] & 1) << 2);
}

/// A box counts as entered when the ray enters it at most kWideBoxSlackUlps units in the last
/// place after it leaves, so that rounding in the slab test never culls a box that a
/// watertight triangle test would hit (Woop, Benthin, Wald 2013, §3.3: robust BVH traversal
/// needs conservative box tests). Eight ulps are a relative margin of 2^-21 to 2^-20.
inline constexpr int32_t kWideBoxSlackUlps = 8;
/// A factor that widens a float by at least those eight ulps, for bounds kept as floats (the
/// packet frustum's tmax).
inline constexpr float kWideBoxSlackFactor = 1.0f + 0x1p-20f;

/// The slab tests take the maximum, minimum and comparison of distances on their bit patterns
/// as signed integers (Embree's single-ray kernels do the same): one cycle each where the
/// float operations take two to four, on the chain from a node's load to the next node's
/// address. Those integers order non-negative floats as the floats are ordered and put every
/// negative float below them, so with tmin >= 0 (Ray) the entry distance is the float maximum,
/// the test decides like the float test, and a box the ray leaves before t = 0 is missed,
/// as it is in floats. Distances are never NaN (WideRay keeps the reciprocals finite).
[[nodiscard]] inline int32_t distance_order(float t) { return std::bit_cast<int32_t>(t); }

#if defined(__AVX2__)
/// distance_order of eight distances.
[[nodiscard]] inline __m256i distance_order(__m256 t) { return _mm256_castps_si256(t); }

/// The lanes where a box is entered (`enter`) at most kWideBoxSlackUlps after it is left
/// (`exit`), both as distance_order: the one rule of the single-ray and packet slab tests.
[[nodiscard]] inline __m256 entered_within_slack(__m256i enter, __m256i exit) {
    // enter <= exit + slack, as exit + slack + 1 > enter.
    return _mm256_castsi256_ps(
        _mm256_cmpgt_epi32(_mm256_add_epi32(exit, _mm256_set1_epi32(kWideBoxSlackUlps + 1)), enter));
}

/// The eight slab tests: the lanes whose boxes the ray enters within [tmin, tmax], and
/// (in `enter`) where it enters each box.
inline __m256 wide_slab_test(const WideNode& node, const WideRay& r, float tmin, float tmax, __m256& enter) {
    auto plane_t = [&](int axis, uint32_t plane) {
        return distance_order(_mm256_fmsub_ps(_mm256_load_ps(node.planes[plane]), _mm256_set1_ps(r.inv_dir[axis]),
                                              _mm256_set1_ps(r.origin_inv_dir[axis])));
    };
    const __m256i near_x = plane_t(0, r.near_plane[0]), far_x = plane_t(0, r.near_plane[0] ^ 1);
    const __m256i near_y = plane_t(1, r.near_plane[1]), far_y = plane_t(1, r.near_plane[1] ^ 1);
    const __m256i near_z = plane_t(2, r.near_plane[2]), far_z = plane_t(2, r.near_plane[2] ^ 1);
    const __m256i enter_order = _mm256_max_epi32(_mm256_max_epi32(near_x, near_y),
                                                 _mm256_max_epi32(near_z, _mm256_set1_epi32(distance_order(tmin))));
    const __m256i exit_order = _mm256_min_epi32(_mm256_min_epi32(far_x, far_y),
                                                _mm256_min_epi32(far_z, _mm256_set1_epi32(distance_order(tmax))));
    enter = _mm256_castsi256_ps(enter_order);
    return entered_within_slack(enter_order, exit_order);
}
#endif

template <bool StoreEnter>
inline uint32_t WideBvh::intersect_node(const WideNode& node, const WideRay& r, float tmin, float tmax,
                                        float* t_enter) {
#if defined(__AVX2__)
    __m256 enter;
    const __m256 hit = wide_slab_test(node, r, tmin, tmax, enter);
    if constexpr (StoreEnter) _mm256_storeu_ps(t_enter, enter);
    return static_cast<uint32_t>(_mm256_movemask_ps(hit));
#else
    uint32_t mask = 0;
    for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
        int32_t enter = distance_order(tmin), exit = distance_order(tmax);
        for (int a = 0; a < 3; ++a) {
            const float t_near = node.planes[r.near_plane[a]][i] * r.inv_dir[a] - r.origin_inv_dir[a];
            const float t_far = node.planes[r.near_plane[a] ^ 1][i] * r.inv_dir[a] - r.origin_inv_dir[a];
            enter = std::max(enter, distance_order(t_near));
            exit = std::min(exit, distance_order(t_far));
        }
        if constexpr (StoreEnter) t_enter[i] = std::bit_cast<float>(enter);
        if (enter <= exit + kWideBoxSlackUlps) mask |= 1u << i;
    }
    return mask;
#endif
}

inline uint32_t WideBvh::intersect_node_far_to_near(const WideNode& node, const WideRay& r, float tmin, float tmax,
                                                    uint32_t* child, float* t_enter) {
#if defined(__AVX2__)
    __m256 enter;
    const __m256 hit = wide_slab_test(node, r, tmin, tmax, enter);
    const __m256i reversed = _mm256_permutevar8x32_epi32(
        _mm256_load_si256(reinterpret_cast<const __m256i*>(node.order)), _mm256_setr_epi32(7, 6, 5, 4, 3, 2, 1, 0));
    const __m256i order = _mm256_and_si256(
        _mm256_srlv_epi32(reversed, _mm256_set1_epi32(static_cast<int>(r.order_shift))), _mm256_set1_epi32(7));
    _mm256_store_ps(t_enter, _mm256_permutevar8x32_ps(enter, order));
    _mm256_store_si256(
        reinterpret_cast<__m256i*>(child),
        _mm256_permutevar8x32_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.child)), order));
    return static_cast<uint32_t>(_mm256_movemask_ps(_mm256_permutevar8x32_ps(hit, order)));
#else
    float slot_enter[WideNode::kWidth];
    const uint32_t slot_mask = intersect_node<true>(node, r, tmin, tmax, slot_enter);
    uint32_t mask = 0;
    for (uint32_t j = 0; j < WideNode::kWidth; ++j) {
        const uint32_t slot = (node.order[WideNode::kWidth - 1 - j] >> r.order_shift) & 7;
        child[j] = node.child[slot];
        t_enter[j] = slot_enter[slot];
        mask |= ((slot_mask >> slot) & 1) << j;
    }
    return mask;
#endif
}

// Inlined into its caller so that the leaf callback's captures (the triangle blocks, the
// watertight test's per-ray constants) are the caller's locals, not loads through a pointer
// to the closure on every leaf: incoherent rays +4 to +8 % (docs/performance.md).
template <bool AnyHit, typename IntersectLeaf, typename Count>
[[gnu::always_inline]] inline bool WideBvh::traverse(Ray& ray, IntersectLeaf&& intersect_leaf,
                                                     const Count& count) const {
    if (nodes_.empty()) return false;
    if constexpr (AnyHit) return traverse_any_hit(ray, intersect_leaf, count);
    const WideRay r(ray);
    const WideNode* const nodes = nodes_.data();
    // A stack of references and one of the distances where the ray enters them, so that
    // both can be pushed by compressing a register.
    uint32_t stack_ref[kWideStackSize];
    float stack_enter[kWideStackSize];
    int top = 0;
    stack_ref[top] = 0;
    stack_enter[top++] = ray.tmin;
    bool hit = false;
    alignas(32) float t_enter[WideNode::kWidth];
    alignas(32) uint32_t child[WideNode::kWidth];
    while (top > 0) {
        --top;
        if (stack_enter[top] > ray.tmax) continue;  // behind a hit found since the push
        uint32_t ref = stack_ref[top];
        bool reached_leaf = true;
        while (!(ref & WideNode::kLeafBit)) {
            const WideNode& node = nodes[ref];
            count.node();
            const uint32_t mask = intersect_node_far_to_near(node, r, ray.tmin, ray.tmax, child, t_enter);
            if (mask == 0) {
                reached_leaf = false;
                break;
            }
            const auto nearest = static_cast<uint32_t>(31 - std::countl_zero(mask));
            const uint32_t others = mask & ~(1u << nearest);
            if (others == 0) {
                ref = child[nearest];
                continue;
            }
            if ((others & (others - 1)) == 0) {
                // Two children hit (the common case): their entry distances order them exactly.
                const auto other = static_cast<uint32_t>(std::countr_zero(others));
                const bool swap = t_enter[other] < t_enter[nearest];
                const uint32_t near = swap ? other : nearest, far = swap ? nearest : other;
                stack_ref[top] = child[far];
                stack_enter[top++] = t_enter[far];
                ref = child[near];
                continue;
            }
            // Push the others far to near (the octant's order approximates the distance
            // order), descend into the nearest.
#if defined(__AVX512VL__)
            const auto lanes = static_cast<__mmask8>(others);
            _mm256_storeu_si256(
                reinterpret_cast<__m256i*>(stack_ref + top),
                _mm256_maskz_compress_epi32(lanes, _mm256_load_si256(reinterpret_cast<const __m256i*>(child))));
            _mm256_storeu_ps(stack_enter + top, _mm256_maskz_compress_ps(lanes, _mm256_load_ps(t_enter)));
            top += std::popcount(others);
#else
            for (uint32_t m = others; m; m &= m - 1) {
                const auto j = static_cast<uint32_t>(std::countr_zero(m));
                stack_ref[top] = child[j];
                stack_enter[top++] = t_enter[j];
            }
#endif
            ref = child[nearest];
        }
        if (!reached_leaf) continue;
        if (intersect_leaf(ref & ~WideNode::kLeafBit, ray)) hit = true;
    }
    return hit;
}

template <typename IntersectLeaf, typename Count>
bool WideBvh::traverse_any_hit(Ray& ray, IntersectLeaf& intersect_leaf, const Count& count) const {
    constexpr bool kTakesPairs = std::is_invocable_r_v<bool, IntersectLeaf&, uint32_t, uint32_t, Ray&>;
    const WideRay r(ray);
    const WideNode* const nodes = nodes_.data();
    uint32_t stack[kWideStackSize];
    int top = 0;
    uint32_t ref = 0;
    // The second of two hit leaves handed on with `ref`, or 0 (no leaf reference is 0).
    uint32_t paired = 0;
    for (;;) {
        while (!(ref & WideNode::kLeafBit)) {
            const WideNode& node = nodes[ref];
            count.node();
            // Any order will do for an any-hit ray; the lowest slot first (the collapse puts
            // leaves there), the others pushed in slot order, was the fastest measured.
            const uint32_t mask = intersect_node<false>(node, r, ray.tmin, ray.tmax, nullptr);
            if (mask == 0) {
                if (top == 0) return false;
                ref = stack[--top];
                continue;
            }
            uint32_t others = mask & (mask - 1);
            ref = node.child[std::countr_zero(mask)];
            if constexpr (kTakesPairs) {
                // The two lowest hit slots both leaves: one call tests them together.
                if ((ref & WideNode::kLeafBit) && others &&
                    (node.child[std::countr_zero(others)] & WideNode::kLeafBit)) {
                    paired = node.child[std::countr_zero(others)];
                    others &= others - 1;
                }
            }
#if defined(__AVX512VL__)
            if ((others & (others - 1)) == 0) {
                // None or one more (the common cases): a plain store.
                if (others) stack[top++] = node.child[std::countr_zero(others)];
            } else {
                // Compressed in a register and stored whole (lanes past the pushed ones are
                // overwritten later): a compressing store to memory would not forward to
                // the next pop's load.
                const __m256i children = _mm256_load_si256(reinterpret_cast<const __m256i*>(node.child));
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(stack + top),
                                    _mm256_maskz_compress_epi32(static_cast<__mmask8>(others), children));
                top += std::popcount(others);
            }
#else
            for (uint32_t m = others; m; m &= m - 1) stack[top++] = node.child[std::countr_zero(m)];
#endif
        }
        if constexpr (kTakesPairs) {
            if (paired != 0) {
                if (intersect_leaf(ref & ~WideNode::kLeafBit, paired & ~WideNode::kLeafBit, ray)) return true;
                paired = 0;
            } else if (intersect_leaf(ref & ~WideNode::kLeafBit, ray)) {
                return true;
            }
        } else if (intersect_leaf(ref & ~WideNode::kLeafBit, ray)) {
            return true;
        }
        if (top == 0) return false;
        ref = stack[--top];
    }
}

}  // namespace glint
