#pragma once
/// \file Parallel binned SAH construction of a binary BVH over abstract primitive bounds.
///
/// Both Glint hierarchies start here: the scene's top level and the triangle meshes' bottom
/// level collapse the binary tree into 8-wide nodes (`WideBvh`).

#include "glint/math/bounds3.h"
#include "glint/util/uninitialized_allocator.h"

#include <cstdint>
#include <functional>
#include <span>

namespace glint {

struct BvhBuildConfig {
    /// Leaves never hold more primitives than this.
    uint32_t max_leaf_size = 8;
    /// Surface-area-heuristic cost of one node traversal relative to one leaf block test.
    float traversal_cost = 1.0f;
    /// Number of SAH bins per axis (at most 64).
    uint32_t bin_count = 32;
    /// Leaf primitives are tested this many at a time (SIMD width of the leaf test), so the
    /// SAH counts leaf cost in whole blocks, as Embree's builders do (log2 of the size).
    uint32_t leaf_block_log2 = 0;
};

/// Flat node, 32 bytes: an inner node stores the index of its first child (the second
/// child follows it); a leaf stores its first entry in the primitive order and a count.
struct BvhNode {
    Bounds3 bounds;
    uint32_t index = 0;
    uint32_t count = 0;  ///< 0 for inner nodes
    [[nodiscard]] bool is_leaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32);

/// A binary BVH: node 0 is the root (no nodes when there is nothing to hit), leaves index
/// `order`, which maps leaf entries to the caller's primitive indices.
struct BinaryBvh {
    UninitializedArray<BvhNode> nodes;
    std::vector<uint32_t> order;
};

/// Above this depth the SAH decides splits; from it on (only for pathological inputs) the
/// builder splits at the object median.
inline constexpr int kMaxSahDepth = 48;
/// The deepest leaf build_binary_bvh makes (the root has depth 0): median splits halve the
/// fewer than 2^32 primitives at every level, so at most 32 levels follow the SAH's.
/// Traversal stacks are sized from it, so no tree can overflow them.
inline constexpr int kMaxBinaryBvhDepth = kMaxSahDepth + 32;

/// Binned SAH build (Wald 2007, "On fast Construction of SAH-based Bounding Volume
/// Hierarchies"), parallel over subtrees and, near the root, over primitives (oneTBB; it
/// runs in the caller's task arena, so the arena decides the thread count). Primitives with
/// empty bounds are left out: they can never be hit. Degenerate (flat, point) bounds are fine.
[[nodiscard]] BinaryBvh build_binary_bvh(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config);

/// Writes the boxes of primitives first, first + 1, ... into `out` (as many as it holds).
/// Called from several threads at once, on disjoint ranges.
using PrimitiveBounds = std::function<void(uint32_t first, std::span<Bounds3> out)>;

/// PrimitiveBounds that copies the boxes from `boxes`, which must outlive it.
[[nodiscard]] PrimitiveBounds bounds_copied_from(std::span<const Bounds3> boxes);

/// The same build over `count` primitives whose boxes `bounds` computes on demand: a large
/// mesh needs no array of every triangle's box, which cost a pass and its page faults.
[[nodiscard]] BinaryBvh build_binary_bvh(uint32_t count, const PrimitiveBounds& bounds, const BvhBuildConfig& config);

}  // namespace glint
