// The collapse of a binary BVH into 8-wide nodes (WideBvh::build): among every way of
// grouping the binary tree's nodes into wide nodes of at most eight children, it picks one
// with the smallest summed surface area of wide nodes, which is the expected number of node
// visits of a ray under the surface area heuristic (Ylitie, Karras, Laine 2017).

#include "glint/accel/sah_builder.h"
#include "glint/accel/wide_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace glint {
namespace {

double summed_node_area(const WideBvh& wide) {
    double sum = 0.0;
    for (const WideNode& node : wide.nodes()) {
        Bounds3 box;
        for (uint32_t i = 0; i < WideNode::kWidth; ++i)
            box = merge(box, Bounds3{Vec3(node.planes[0][i], node.planes[2][i], node.planes[4][i]),
                                     Vec3(node.planes[1][i], node.planes[3][i], node.planes[5][i])});
        sum += box.half_area();
    }
    return sum;
}

/// The smallest summed area by listing every collapse: a wide node made from binary node k
/// has as children a frontier of k's subtree (at most eight nodes below k that together
/// cover its leaves), and each inner node of the frontier is a wide node again.
class EveryCollapse {
public:
    explicit EveryCollapse(const BinaryBvh& binary) : binary_(binary) {}

    double best_wide_node(uint32_t k) {
        if (auto it = best_.find(k); it != best_.end()) return it->second;
        const BvhNode& node = binary_.nodes[k];
        double best = std::numeric_limits<double>::infinity();
        for (const auto& [size, cost] : frontiers(node.index))
            for (const auto& [other_size, other_cost] : frontiers(node.index + 1))
                if (size + other_size <= WideNode::kWidth) best = std::min(best, cost + other_cost);
        best += node.bounds.half_area();
        best_[k] = best;
        return best;
    }

private:
    /// Every frontier of k's subtree (k itself included) as (members, summed area of the
    /// wide nodes below it).
    std::vector<std::pair<uint32_t, double>> frontiers(uint32_t k) {
        const BvhNode& node = binary_.nodes[k];
        if (node.is_leaf()) return {{1u, 0.0}};
        std::vector<std::pair<uint32_t, double>> all{{1u, best_wide_node(k)}};
        for (const auto& [size, cost] : frontiers(node.index))
            for (const auto& [other_size, other_cost] : frontiers(node.index + 1))
                if (size + other_size <= WideNode::kWidth) all.emplace_back(size + other_size, cost + other_cost);
        return all;
    }

    const BinaryBvh& binary_;
    std::map<uint32_t, double> best_;
};

TEST(WideCollapse, PicksTheGroupingWithTheFewestExpectedNodeVisits) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> uniform(-10.0f, 10.0f), size(0.05f, 4.0f);
        std::vector<Bounds3> boxes(32);
        for (Bounds3& b : boxes) {
            const Vec3 lo(uniform(rng), uniform(rng), uniform(rng));
            b = Bounds3(lo, lo + Vec3(size(rng), size(rng), size(rng)));
        }
        const BvhBuildConfig config{.max_leaf_size = 1};
        const BinaryBvh binary = build_binary_bvh(boxes, config);
        WideBvh wide;
        wide.build(boxes, config);
        const double best = EveryCollapse(binary).best_wide_node(0);
        EXPECT_NEAR(summed_node_area(wide), best, 1e-6 * best) << "seed " << seed;
    }
}

}  // namespace
}  // namespace glint
