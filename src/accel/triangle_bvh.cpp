#include "glint/accel/triangle_bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <limits>

namespace glint {

void TriangleBvh::build(std::span<const Vec3> positions, std::span<const uint32_t> indices) {
    const auto count = static_cast<uint32_t>(indices.size() / 3);
    // The builder asks for the triangles' boxes as it fills its references.
    auto boxes = [&](uint32_t first, std::span<Bounds3> out) {
        for (size_t i = 0; i < out.size(); ++i) {
            Bounds3 b;
            for (int k = 0; k < 3; ++k) b.extend(positions[indices[3 * (first + i) + k]]);
            out[i] = b;
        }
    };
    // At most four triangles per leaf: one block, so leaf k's triangles become block k.
    BvhBuildConfig config;
    config.max_leaf_size = TriangleBlock::kWidth;
    config.leaf_block_log2 = 2;
    wide_.build(count, boxes, config);
    const std::span<const WideLeaf> leaves = wide_.leaves();
    const std::span<const uint32_t> order = wide_.primitive_order();
    // Left unwritten: the loop below writes every lane of every block, on every thread.
    blocks_.resize(leaves.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.size(), 1u << 12), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t l = r.begin(); l < r.end(); ++l) {
            TriangleBlock& block = blocks_[l];
            for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane) {
                // Unused lanes get NaN vertices: every comparison fails, never a hit.
                block.triangle[lane] = kNoHit;
                if (lane >= leaves[l].count) {
                    for (auto& vertex : block.v)
                        for (auto& axis : vertex) axis[lane] = std::numeric_limits<float>::quiet_NaN();
                    continue;
                }
                const uint32_t tri = order[leaves[l].first + lane];
                block.triangle[lane] = tri;
                for (int vtx = 0; vtx < 3; ++vtx) {
                    const Vec3& p = positions[indices[3 * size_t(tri) + vtx]];
                    for (int a = 0; a < 3; ++a) block.v[vtx][a][lane] = p[a];
                }
            }
        }
    });
    // The leaf index is already the block index; encoding frees the leaf ranges and the
    // order, which the blocks now hold.
    wide_.encode_leaves([](uint32_t leaf) { return leaf; });
}

}  // namespace glint
