#include "glint/accel/wide_bvh.h"

#include <algorithm>
#include <limits>

namespace glint {

namespace {

/// Turns binary nodes into wide ones, depth first.
class Collapser {
public:
    Collapser(const BinaryBvh& binary, std::vector<WideNode>& nodes, LargeArray<WideLeaf>& leaves)
        : binary_(binary), nodes_(nodes), leaves_(leaves) {}

    /// Fills wide node `index` with the subtree of binary node `root`.
    void fill(uint32_t index, uint32_t root) {
        uint32_t slots[WideNode::kWidth];
        const uint32_t used = slots_of(root, slots);
        // Leaves in the low slots, where any-hit rays start; a node's leaves and its child
        // nodes each lie together in memory, which the hardware prefetcher likes.
        std::stable_partition(slots, slots + used, [&](uint32_t k) { return binary_.nodes[k].is_leaf(); });
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

    /// The number of wide nodes fill(·, root) makes: the planned collapse read off as fill
    /// does, without writing, so that the nodes are allocated once at their final size.
    [[nodiscard]] size_t count_nodes(uint32_t root) const {
        uint32_t slots[WideNode::kWidth];
        const uint32_t used = slots_of(root, slots);
        size_t count = 1;
        for (uint32_t i = 0; i < used; ++i)
            if (!binary_.nodes[slots[i]].is_leaf()) count += count_nodes(slots[i]);
        return count;
    }

    /// Plans the collapse that minimises the summed surface area of the wide nodes (the
    /// expected number of node visits; the leaves are the binary tree's either way): the
    /// dynamic program of Ylitie, Karras and Laine 2017 ("Efficient Incoherent Ray
    /// Traversal on GPUs Through Compressed Wide BVHs", §3), without its leaf merging.
    void plan() {
        const size_t n = binary_.nodes.size();
        plan_.assign(n, {});
        // build_binary_bvh numbers children after their parent, so walking backwards meets
        // them first.
        for (size_t k = n; k-- > 0;) {
            const BvhNode& node = binary_.nodes[k];
            Plan& p = plan_[k];
            if (node.is_leaf()) continue;  // one slot, cost 0 (leaves are the same in any collapse)
            const Plan& a = plan_[node.index];
            const Plan& b = plan_[node.index + 1];
            // best[j - 1]: the two subtrees in at most j slots, each taking at least one (so
            // at most seven).
            float best[WideNode::kWidth];
            uint8_t split[WideNode::kWidth];
            for (uint32_t j = 1; j <= WideNode::kWidth; ++j) {
                // From two slots on, the first subtree in one slot is where the search starts,
                // so that a split is chosen even when no cost compares (NaN bounds of a
                // hostile mesh: the split stayed 0 and distribute() indexed split[-1]).
                best[j - 1] = j >= 2 ? a.cost[0] + b.cost[j - 2] : std::numeric_limits<float>::infinity();
                split[j - 1] = j >= 2 ? 1 : 0;
                for (uint32_t left = 2; left < j; ++left) {
                    const float c = a.cost[left - 1] + b.cost[j - left - 1];
                    if (c < best[j - 1]) {
                        best[j - 1] = c;
                        split[j - 1] = static_cast<uint8_t>(left);
                    }
                }
            }
            // In one slot the node is a wide node of its own: its area, plus its subtrees
            // spread over eight slots.
            p.own_split = split[WideNode::kWidth - 1];
            p.cost[0] = node.bounds.half_area() + best[WideNode::kWidth - 1];
            p.split[0] = 0;
            for (uint32_t j = 2; j < WideNode::kWidth; ++j) {
                const bool open = best[j - 1] < p.cost[j - 2];
                p.cost[j - 1] = open ? best[j - 1] : p.cost[j - 2];
                p.split[j - 1] = open ? split[j - 1] : p.split[j - 2];
            }
        }
    }

private:
    /// A binary node's cost and choice in at most j + 1 slots of a wide node above it (a
    /// parent leaves at least one of its eight to the other subtree): split[j] slots for its
    /// first child and the rest for the second, or 0 to keep it in one slot. own_split is
    /// the first child's share of the eight slots when the node is a wide node of its own.
    struct Plan {
        float cost[WideNode::kWidth - 1] = {};
        uint8_t split[WideNode::kWidth - 1] = {};
        uint8_t own_split = 0;
    };

    /// The binary nodes that become the children of the wide node made from binary node
    /// `root`, as the plan distributes them (a leaf root is its own only child); their count.
    uint32_t slots_of(uint32_t root, uint32_t* slots) const {
        uint32_t used = 0;
        const BvhNode& r = binary_.nodes[root];
        if (r.is_leaf()) {
            slots[used++] = root;
        } else {
            distribute(r.index, plan_[root].own_split, slots, used);
            distribute(r.index + 1, WideNode::kWidth - plan_[root].own_split, slots, used);
        }
        return used;
    }

    /// Appends the slots binary node `k` takes when given `count` of them by the plan.
    void distribute(uint32_t k, uint32_t count, uint32_t* slots, uint32_t& used) const {
        const BvhNode& node = binary_.nodes[k];
        const uint32_t left = node.is_leaf() ? 0 : plan_[k].split[count - 1];
        if (left == 0) {
            slots[used++] = k;
            return;
        }
        distribute(node.index, left, slots, used);
        distribute(node.index + 1, count - left, slots, used);
    }

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
    LargeArray<WideLeaf>& leaves_;
    LargeArray<Plan> plan_;
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
    leaves_.reserve(binary_leaves);
    Collapser collapser(binary, nodes_, leaves_);
    collapser.plan();
    // Reserved at the exact count: reserving one node per binary leaf and then shrinking to
    // fit copied the nodes once more and faulted in their pages twice (docs/performance.md,
    // "The build's page faults").
    nodes_.reserve(collapser.count_nodes(0));
    nodes_.emplace_back();
    collapser.fill(0, 0);
    order_ = std::move(binary.order);
}

}  // namespace glint
