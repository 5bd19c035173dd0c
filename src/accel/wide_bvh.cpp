#include "glint/accel/wide_bvh.h"

namespace glint {

namespace {

/// Turns binary nodes into wide ones, depth first, so that a wide node's children and
/// the leaves below it lie close together in memory.
class Collapser {
public:
    Collapser(const BinaryBvh& binary, std::vector<WideNode>& nodes, std::vector<WideLeaf>& leaves)
        : binary_(binary), nodes_(nodes), leaves_(leaves) {}

    /// Creates the wide node that replaces binary node `root` and returns its index.
    uint32_t collapse(uint32_t root) {
        uint32_t slots[WideNode::kWidth];
        uint32_t used = 0;
        const BvhNode& r = binary_.nodes[root];
        if (r.is_leaf()) {
            slots[used++] = root;
        } else {
            slots[used++] = r.index;
            slots[used++] = r.index + 1;
        }
        // Open the inner child with the largest surface area (the one most rays enter)
        // until all eight slots are used.
        while (used < WideNode::kWidth) {
            int best = -1;
            float best_area = -1.0f;
            for (uint32_t i = 0; i < used; ++i) {
                const BvhNode& n = binary_.nodes[slots[i]];
                if (!n.is_leaf() && n.bounds.half_area() > best_area) {
                    best_area = n.bounds.half_area();
                    best = int(i);
                }
            }
            if (best < 0) break;
            const uint32_t first = binary_.nodes[slots[best]].index;
            slots[best] = first;
            slots[used++] = first + 1;
        }
        const auto index = static_cast<uint32_t>(nodes_.size());
        nodes_.emplace_back();
        {
            WideNode& w = nodes_[index];
            for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
                const Bounds3 b = i < used ? binary_.nodes[slots[i]].bounds : Bounds3{};
                for (int a = 0; a < 3; ++a) {
                    w.planes[2 * a][i] = b.lo[a];
                    w.planes[2 * a + 1][i] = b.hi[a];
                }
                w.child[i] = WideNode::kLeafBit;  // unused slots: never entered
            }
        }
        for (uint32_t i = 0; i < used; ++i) {
            const BvhNode& n = binary_.nodes[slots[i]];
            uint32_t child;
            if (n.is_leaf()) {
                child = WideNode::kLeafBit | static_cast<uint32_t>(leaves_.size());
                leaves_.push_back({n.index, n.count});
            } else {
                child = collapse(slots[i]);
            }
            nodes_[index].child[i] = child;  // nodes_ may have grown: index again
        }
        return index;
    }

private:
    const BinaryBvh& binary_;
    std::vector<WideNode>& nodes_;
    std::vector<WideLeaf>& leaves_;
};

}  // namespace

void WideBvh::build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config) {
    nodes_.clear();
    leaves_.clear();
    order_.clear();
    bounds_ = Bounds3{};
    BinaryBvh binary = build_binary_bvh(primitive_bounds, config);
    if (binary.nodes.empty()) return;
    bounds_ = binary.nodes[0].bounds;
    size_t binary_leaves = 0;
    for (const BvhNode& n : binary.nodes) binary_leaves += n.is_leaf() ? 1 : 0;
    // Each wide node absorbs at least one binary inner node (one per binary leaf, minus one).
    nodes_.reserve(binary_leaves);
    leaves_.reserve(binary_leaves);
    Collapser(binary, nodes_, leaves_).collapse(0);
    nodes_.shrink_to_fit();
    order_ = std::move(binary.order);
}

}  // namespace glint
