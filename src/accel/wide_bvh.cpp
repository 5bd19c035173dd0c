#include "glint/accel/wide_bvh.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <bit>
#include <limits>

namespace glint {

namespace {

/// Binary trees of at least this many nodes are planned and collapsed with their subtrees
/// in parallel, down to these depths (binary levels for the plan, wide levels for the
/// rest): enough tasks for a few cores, and none for the small trees of a scene's many
/// small meshes.
constexpr size_t kParallelCollapseNodes = size_t(1) << 14;
constexpr int kParallelPlanDepth = 8;
constexpr int kParallelFillDepth = 3;

/// Runs body(i) for each i < count, in parallel when asked.
template <typename Body>
void for_each_index(bool parallel, uint32_t count, const Body& body) {
    if (parallel)
        tbb::parallel_for(0u, count, [&](uint32_t i) { body(i); });
    else
        for (uint32_t i = 0; i < count; ++i) body(i);
}

/// Where key i of eight comes in their stable ascending order: after every smaller key and
/// every equal one before it. The eight ranks of eight keys are a sort without branches:
/// the insertion sort before it compared keys no predictor could guess and was half of
/// the collapse's time; counted with one comparison of all eight at once, as here, the
/// ranks cost a quarter of what they did one pair at a time.
inline uint32_t stable_rank(const float* key, uint32_t i) {
    const uint32_t before = (1u << i) - 1;  // bit j for each j < i
#if defined(__SSE2__)
    const __m128 low = _mm_loadu_ps(key), high = _mm_loadu_ps(key + 4), k = _mm_set1_ps(key[i]);
    const auto less = uint32_t(_mm_movemask_ps(_mm_cmplt_ps(low, k)) | _mm_movemask_ps(_mm_cmplt_ps(high, k)) << 4);
    const auto equal = uint32_t(_mm_movemask_ps(_mm_cmpeq_ps(low, k)) | _mm_movemask_ps(_mm_cmpeq_ps(high, k)) << 4);
#else
    uint32_t less = 0, equal = 0;
    for (uint32_t j = 0; j < 8; ++j) {
        less |= uint32_t(key[j] < key[i]) << j;
        equal |= uint32_t(key[j] == key[i]) << j;
    }
#endif
    return uint32_t(std::popcount(less | (equal & before)));
}

/// Turns binary nodes into wide ones: the plan, then the size of each wide subtree, then
/// the nodes, each subtree written into the nodes and leaves that a serial depth-first fill
/// would give it (a node's children together after it, then their subtrees in slot
/// order), so that the tree is the same whatever the number of threads.
class Collapser {
public:
    Collapser(const BinaryBvh& binary, WideNodeArray& nodes, std::vector<WideLeaf>& leaves)
        : binary_(binary), nodes_(nodes), leaves_(leaves), parallel_(binary.nodes.size() >= kParallelCollapseNodes) {}

    void collapse() {
        plan_.resize(binary_.nodes.size());
        plan_subtree(0, 0);
        sizes_.resize(binary_.nodes.size());
        const Size total = measure(0, 0);
        // Sized once, at the final count: reserving one node per binary leaf and shrinking
        // to fit copied the nodes again and faulted in their pages twice (docs/performance.md,
        // "The build's page faults"). The nodes are left unwritten (UninitializedArray)
        // for fill(), which writes every byte of them, so their pages fault in on every
        // thread.
        nodes_.resize(total.nodes);
        leaves_.resize(total.leaves);
        fill(0, 0, Size{1, 0}, 0);
    }

private:
    /// A binary node's cost and choice in at most j + 1 slots of a wide node above it (a
    /// parent leaves at least one of its eight to the other subtree): split[j] slots for its
    /// first child and the rest for the second, or 0 to keep it in one slot. own_split is
    /// the first child's share of the eight slots when the node is a wide node of its own.
    /// A leaf's plan is zero: one slot, cost 0 (leaves are the same in any collapse).
    struct Plan {
        float cost[WideNode::kWidth - 1] = {};
        uint8_t split[WideNode::kWidth - 1] = {};
        uint8_t own_split = 0;
    };

    /// Wide nodes and leaves: a subtree's counts, or the first of each a subtree may use.
    struct Size {
        uint32_t nodes = 0;
        uint32_t leaves = 0;
    };

    /// Plans the collapse that minimises the summed surface area of the wide nodes (the
    /// expected number of node visits; the leaves are the binary tree's either way): the
    /// dynamic program of Ylitie, Karras and Laine 2017 ("Efficient Incoherent Ray
    /// Traversal on GPUs Through Compressed Wide BVHs", §3), without its leaf merging;
    /// children before parents.
    void plan_subtree(uint32_t k, int depth) {
        const BvhNode& node = binary_.nodes[k];
        if (node.is_leaf()) {
            plan_[k] = Plan{};
            return;
        }
        if (parallel_ && depth < kParallelPlanDepth) {
            tbb::parallel_invoke([&] { plan_subtree(node.index, depth + 1); },
                                 [&] { plan_subtree(node.index + 1, depth + 1); });
        } else {
            plan_subtree(node.index, depth + 1);
            plan_subtree(node.index + 1, depth + 1);
        }
        plan_node(k);
    }

    /// The plan of inner binary node `k`, from its children's.
    void plan_node(uint32_t k) {
        const BvhNode& node = binary_.nodes[k];
        Plan& p = plan_[k];
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

    /// The size of the wide subtree that fill(·, root) makes, recorded for each of its nodes.
    Size measure(uint32_t root, int depth) {
        uint32_t slots[WideNode::kWidth];
        const uint32_t used = slots_of(root, slots);
        Size child[WideNode::kWidth];
        for_each_index(parallel_ && depth < kParallelFillDepth, used, [&](uint32_t i) {
            child[i] = binary_.nodes[slots[i]].is_leaf() ? Size{0, 1} : measure(slots[i], depth + 1);
        });
        Size size{1, 0};
        for (uint32_t i = 0; i < used; ++i) {
            size.nodes += child[i].nodes;
            size.leaves += child[i].leaves;
        }
        sizes_[root] = size;
        return size;
    }

    /// Fills wide node `index` with the subtree of binary node `root`; its children and
    /// their subtrees take the nodes and leaves from `next` on.
    void fill(uint32_t index, uint32_t root, Size next, int depth) {
        uint32_t slots[WideNode::kWidth];
        const uint32_t used = slots_of(root, slots);
        leaves_first(slots, used);
        uint32_t inner = 0;
        for (uint32_t i = 0; i < used; ++i) inner += binary_.nodes[slots[i]].is_leaf() ? 0 : 1;
        Size below{next.nodes + inner, next.leaves + (used - inner)};  // where the grandchildren go
        Size child_next[WideNode::kWidth];
        WideNode& node = nodes_[index];
        for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
            const Bounds3 b = i < used ? binary_.nodes[slots[i]].bounds : Bounds3{};
            for (int a = 0; a < 3; ++a) {
                node.planes[2 * a][i] = b.lo[a];
                node.planes[2 * a + 1][i] = b.hi[a];
            }
            node.child[i] = WideNode::kLeafBit;  // unused slots: never entered
            if (i >= used) continue;
            const BvhNode& n = binary_.nodes[slots[i]];
            if (n.is_leaf()) {
                node.child[i] = WideNode::kLeafBit | next.leaves;
                leaves_[next.leaves++] = {n.index, n.count};
            } else {
                node.child[i] = next.nodes++;
                child_next[i] = below;
                below.nodes += sizes_[slots[i]].nodes - 1;
                below.leaves += sizes_[slots[i]].leaves;
            }
        }
        set_child_order(node, slots, used);
        for_each_index(parallel_ && depth < kParallelFillDepth, used, [&](uint32_t i) {
            if (!binary_.nodes[slots[i]].is_leaf()) fill(node.child[i], slots[i], child_next[i], depth + 1);
        });
    }

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

    /// Leaves in the low slots, where any-hit rays start; a node's leaves and its child nodes
    /// each lie together in memory, which the hardware prefetcher likes. A stable partition
    /// by hand: std::stable_partition takes a heap buffer on every call.
    void leaves_first(uint32_t* slots, uint32_t used) const {
        uint32_t inner[WideNode::kWidth];
        uint32_t leaves = 0, inners = 0;
        for (uint32_t i = 0; i < used; ++i) {
            if (binary_.nodes[slots[i]].is_leaf())
                slots[leaves++] = slots[i];
            else
                inner[inners++] = slots[i];
        }
        std::copy(inner, inner + inners, slots + leaves);
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
        Vec3 centre[WideNode::kWidth];
        for (uint32_t i = 0; i < used; ++i) centre[i] = binary_.nodes[slots[i]].bounds.center();
        std::fill(std::begin(node.order), std::end(node.order), 0u);
        for (uint32_t octant = 0; octant < 8; ++octant) {
            float key[WideNode::kWidth];
            for (uint32_t i = 0; i < WideNode::kWidth; ++i) {
                key[i] = std::numeric_limits<float>::infinity();
                if (i >= used) continue;
                float k = 0.0f;
                for (int a = 0; a < 3; ++a) k += (octant >> a & 1) ? -centre[i][a] : centre[i][a];
                key[i] = k == k ? k : std::numeric_limits<float>::infinity();  // NaN (a hostile mesh's box) last
            }
            for (uint32_t i = 0; i < WideNode::kWidth; ++i) node.order[stable_rank(key, i)] |= i << (3 * octant);
        }
    }

    const BinaryBvh& binary_;
    WideNodeArray& nodes_;
    std::vector<WideLeaf>& leaves_;
    const bool parallel_;
    // Left unwritten (UninitializedArray) until the passes write them, on every thread: zeroed,
    // they were a serial pass and 6 MB of page faults on one thread for the dragon.
    UninitializedArray<Plan> plan_;   // per binary node
    UninitializedArray<Size> sizes_;  // per binary node that becomes a wide node
};

}  // namespace

void WideBvh::build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config) {
    build(static_cast<uint32_t>(primitive_bounds.size()), bounds_copied_from(primitive_bounds), config);
}

void WideBvh::build(uint32_t count, const PrimitiveBounds& bounds, const BvhBuildConfig& config) {
    nodes_.clear();
    leaves_.clear();
    order_.clear();
    bounds_ = Bounds3{};
    BinaryBvh binary = build_binary_bvh(count, bounds, config);
    if (binary.nodes.empty()) return;
    bounds_ = binary.nodes[0].bounds;
    Collapser(binary, nodes_, leaves_).collapse();
    order_ = std::move(binary.order);
}

}  // namespace glint
