#include "glint/accel/wide_bvh.h"

#include <algorithm>
#include <limits>

namespace glint {

namespace {

/// Turns binary nodes into wide ones, depth first.
class Collapser {
public:
    Collapser(const BinaryBvh& binary, std::vector<WideNode>& nodes, std::vector<WideLeaf>& leaves)
        : binary_(binary), nodes_(nodes), leaves_(leaves) {}

    /// Fills wide node `index` with the subtree of binary node `root`.
    void fill(uint32_t index, uint32_t root) {
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
        // Leaves first, then the inner children side by side: a node's leaves and its
        // child nodes each lie together in memory, which the hardware prefetcher likes.
        uint32_t inner = 0;
        for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
            const Bounds3 b = i < used ? binary_.nodes[slots[i]].bounds : Bounds3{};
            for (int a = 0; a < 3; ++a) {
                nodes_[index].planes[2 * a][i] = b.lo[a];
                nodes_[index].planes[2 * a + 1][i] = b.hi[a];
            }
            nodes_[index].child[i] = WideNode::kLeafBit;  // unused slots: never entered
            if (i >= used) continue;
            const BvhNode& n = binary_.nodes[slots[i]];
            if (n.is_leaf()) {
                nodes_[index].child[i] = WideNode::kLeafBit | static_cast<uint32_t>(leaves_.size());
                leaves_.push_back({n.index, n.count});
            } else {
                ++inner;
            }
        }
        set_child_order(nodes_[index], slots, used);
        const auto first_child = static_cast<uint32_t>(nodes_.size());
        nodes_.resize(nodes_.size() + inner);
        uint32_t next = first_child;
        for (uint32_t i = 0; i < used; ++i)
            if (!binary_.nodes[slots[i]].is_leaf()) nodes_[index].child[i] = next++;
        for (uint32_t i = 0; i < used; ++i)
            if (!binary_.nodes[slots[i]].is_leaf()) fill(nodes_[index].child[i], slots[i]);
    }

private:
    /// For each ray octant, the used slots sorted by how far along the octant's diagonal
    /// their centres lie (a ray heading that way meets them in about that order), then the
    /// unused ones.
    void set_child_order(WideNode& node, const uint32_t* slots, uint32_t used) const {
        std::fill(std::begin(node.order), std::end(node.order), 0u);
        for (uint32_t octant = 0; octant < 8; ++octant) {
            float key[WideNode::kWidth];
            uint32_t sorted[WideNode::kWidth];
            for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
                sorted[i] = i;
                key[i] = std::numeric_limits<float>::infinity();
                if (i >= used) continue;
                const Vec3 centre = binary_.nodes[slots[i]].bounds.center();
                key[i] = 0.0f;
                for (int a = 0; a < 3; ++a) key[i] += (octant >> a & 1) ? -centre[a] : centre[a];
            }
            std::stable_sort(sorted, sorted + WideNode::kWidth,
                             [&](uint32_t a, uint32_t b) { return key[a] < key[b]; });
            for (uint32_t k = 0; k < WideNode::kWidth; ++k) node.order[k] |= sorted[k] << (3 * octant);
        }
    }

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
    nodes_.emplace_back();
    Collapser(binary, nodes_, leaves_).fill(0, 0);
    nodes_.shrink_to_fit();
    order_ = std::move(binary.order);
}

}  // namespace glint
