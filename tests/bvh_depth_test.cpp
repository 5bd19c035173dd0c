// The binary BVH's depth bound, which sizes the wide BVH's traversal stack: a pathological
// input builds a tree deeper than a small fixed stack would hold, and traversal still
// visits every primitive (the scene's top level is such a tree over arbitrary boxes). An overflow may go unnoticed in
// Release; under AddressSanitizer (CI's `loader` label) it fails.

#include "glint/accel/wide_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace glint {
namespace {

/// Depth of the deepest leaf below `node` (the root has depth 0).
int deepest_leaf(std::span<const BvhNode> nodes, uint32_t node, int depth) {
    const BvhNode& n = nodes[node];
    if (n.is_leaf()) return depth;
    return std::max(deepest_leaf(nodes, n.index, depth + 1), deepest_leaf(nodes, n.index + 1, depth + 1));
}

TEST(BvhDepth, APathologicalTreeStaysWithinTheBoundAndIsFullyTraversed) {
    // Sixty boxes growing threefold along x: with two bins only the largest lies in the
    // upper bin, so every SAH level peels off one box; beneath them 2^18 identical boxes,
    // which only median splits divide (18 more levels). Every box contains the segment
    // x ∈ [0, 1] of the x axis, so a ray along it enters every node.
    std::vector<Bounds3> boxes;
    for (int k = 1; k <= 60; ++k) boxes.emplace_back(Vec3(0.0f, -1.0f, -1.0f), Vec3(std::pow(3.0f, float(k)), 1.0f, 1.0f));
    const uint32_t cluster = 1u << 18;
    boxes.insert(boxes.end(), cluster, Bounds3(Vec3(0.0f, -1.0f, -1.0f), Vec3(1.0f, 1.0f, 1.0f)));
    BvhBuildConfig config;
    config.bin_count = 2;
    config.max_leaf_size = 1;
    const int depth = deepest_leaf(build_binary_bvh(boxes, config).nodes, 0, 0);
    EXPECT_GT(depth, 64) << "not pathological enough to overflow a 64-entry stack";
    EXPECT_LE(depth, kMaxBinaryBvhDepth);

    // Every child of every node is hit at the same distance, so the traversal pushes the
    // others at every level on its way to the first leaf.
    WideBvh wide;
    wide.build(boxes, config);
    for (const bool any_hit : {false, true}) {
        Ray ray(Vec3(-1.0f, 0.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f));
        std::size_t visited = 0;
        auto visit = [&](uint32_t leaf, Ray&) {
            visited += wide.leaves()[leaf].count;
            return false;  // no hit: the traversal must go on to every leaf
        };
        const bool hit = any_hit ? wide.traverse<true>(ray, visit) : wide.traverse<false>(ray, visit);
        EXPECT_FALSE(hit);
        EXPECT_EQ(visited, boxes.size()) << (any_hit ? "any hit" : "closest hit");
    }
}

}  // namespace
}  // namespace glint
