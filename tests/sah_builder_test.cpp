// The binned SAH build (accel/sah_builder.h) splits where the surface-area heuristic says:
// separated clusters part at the root where the heuristic's sum says, along whichever axis
// separates them and however many empty bins lie between; a box no split can improve
// stays a leaf, and every primitive is in exactly one leaf; primitives that fit one leaf
// split only where the split costs less; and where every primitive has a
// bin of its own, the root takes the cheapest of all splits, by the full heuristic, and so
// does a child, binned over its own centroids; and every node's box is exactly the union of
// its primitives' boxes; boxes computed on demand give the same tree, without the empty ones.

#include "glint/accel/sah_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <random>
#include <span>
#include <vector>

namespace glint {
namespace {

/// `count` unit cubes in a row along `axis`, starting at `start` on it.
void add_row(std::vector<Bounds3>& boxes, int axis, float start, int count) {
    for (int i = 0; i < count; ++i) {
        Vec3 lo(0.0f), hi(1.0f);
        lo[axis] = start + 1.5f * float(i);
        hi[axis] = lo[axis] + 1.0f;
        boxes.emplace_back(lo, hi);
    }
}

/// The leaf entries below `node`, in the order of `bvh.order`.
void leaves_below(const BinaryBvh& bvh, uint32_t node, std::vector<uint32_t>& out) {
    const BvhNode& n = bvh.nodes[node];
    if (n.is_leaf()) {
        out.insert(out.end(), bvh.order.begin() + n.index, bvh.order.begin() + n.index + n.count);
        return;
    }
    leaves_below(bvh, n.index, out);
    leaves_below(bvh, n.index + 1, out);
}

TEST(SahBuilder, SeparatedClustersPartAtTheRootWhereTheHeuristicSays) {
    for (int axis = 0; axis < 3; ++axis) {
        // Rows of 3, 3 and 10 cubes at 0, 500 and 1000 along `axis`, with empty bins between.
        // The cheapest root split (half areas about 2L + 1 for a row of length L) puts the
        // two short rows together: 1009 * 6 + 30 * 10 = 6354, against 9 * 3 + 1015 * 13 =
        // 13222 for the first row alone; the object median (8 and 8) would cut the long row.
        std::vector<Bounds3> boxes;
        add_row(boxes, axis, 0.0f, 3);
        add_row(boxes, axis, 500.0f, 3);
        add_row(boxes, axis, 1000.0f, 10);
        const BinaryBvh bvh = build_binary_bvh(boxes, {});
        ASSERT_FALSE(bvh.nodes.empty());
        ASSERT_FALSE(bvh.nodes[0].is_leaf()) << "axis " << axis;
        const uint32_t first = bvh.nodes[0].index;
        for (uint32_t child : {first, first + 1}) {
            std::vector<uint32_t> ids;
            leaves_below(bvh, child, ids);
            std::sort(ids.begin(), ids.end());
            const bool near = ids.front() == 0;
            std::vector<uint32_t> expected(near ? 6 : 10);
            for (uint32_t i = 0; i < expected.size(); ++i) expected[i] = (near ? 0 : 6) + i;
            EXPECT_EQ(ids, expected) << "axis " << axis;
            const Bounds3& b = bvh.nodes[child].bounds;
            EXPECT_EQ(b.lo[axis], near ? 0.0f : 1000.0f) << "axis " << axis;
            EXPECT_EQ(b.hi[axis], near ? 504.0f : 1014.5f) << "axis " << axis;
        }
    }
}

TEST(SahBuilder, ABoxNoSplitImprovesStaysOneLeafAndEveryPrimitiveIsInOneLeaf) {
    // Four identical cubes: any split leaves two children as large as the parent.
    const std::vector<Bounds3> same(4, Bounds3(Vec3(0.0f), Vec3(1.0f)));
    const BinaryBvh leaf = build_binary_bvh(same, {});
    ASSERT_EQ(leaf.nodes.size(), 1u);
    EXPECT_EQ(leaf.nodes[0].count, 4u);

    // A grid of 20 x 20 x 20 cubes: every one in exactly one leaf, no leaf above the limit.
    std::vector<Bounds3> grid;
    for (int z = 0; z < 20; ++z)
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 20; ++x)
                grid.emplace_back(Vec3(float(x), float(y), float(z)) * 2.0f,
                                  Vec3(float(x), float(y), float(z)) * 2.0f + Vec3(1.0f));
    BvhBuildConfig config;
    config.max_leaf_size = 4;
    const BinaryBvh bvh = build_binary_bvh(grid, config);
    std::vector<uint32_t> ids;
    leaves_below(bvh, 0, ids);
    std::sort(ids.begin(), ids.end());
    ASSERT_EQ(ids.size(), grid.size());
    for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i);
    for (const BvhNode& n : bvh.nodes) EXPECT_LE(n.count, 4u);
}

TEST(SahBuilder, PrimitivesThatFitOneLeafSplitOnlyWhereTheSplitCostsLess) {
    // Unit cubes 100 apart along x: a long thin box whose children are small.
    auto spread = [](int count) {
        std::vector<Bounds3> boxes;
        for (int i = 0; i < count; ++i)
            boxes.emplace_back(Vec3(100.0f * float(i), 0, 0), Vec3(100.0f * float(i) + 1, 1, 1));
        return boxes;
    };
    // Blocks of one: the leaf of two costs 2A = 406, the split A + 3 + 3 = 209.
    const BinaryBvh two = build_binary_bvh(spread(2), {});
    ASSERT_FALSE(two.nodes.empty());
    EXPECT_FALSE(two.nodes[0].is_leaf());

    // Blocks of four: four cubes are one block, A = 603, and any split costs at least the
    // traversal's A, so they stay a leaf...
    BvhBuildConfig blocks_of_four;
    blocks_of_four.leaf_block_log2 = 2;
    const BinaryBvh four = build_binary_bvh(spread(4), blocks_of_four);
    ASSERT_EQ(four.nodes.size(), 1u);
    EXPECT_EQ(four.nodes[0].count, 4u);

    // ...unless a traversal costs a quarter of a block: two pairs cost 603 / 4 + 203 + 203 = 557.
    BvhBuildConfig cheap_traversal = blocks_of_four;
    cheap_traversal.traversal_cost = 0.25f;
    const BinaryBvh split = build_binary_bvh(spread(4), cheap_traversal);
    ASSERT_FALSE(split.nodes.empty());
    EXPECT_FALSE(split.nodes[0].is_leaf());
}

/// Eight boxes of random extents whose centres lie 10 apart on every axis (in a random order
/// per axis), so that each falls in a bin of its own and the binned search sees every split
/// in centroid order; and, by brute force, the side of the split of least
/// area(left) * |left| + area(right) * |right|. Empty when the two best splits nearly tie,
/// so that rounding may pick either.
struct SplitTrial {
    static constexpr int kBoxes = 8;
    std::vector<Bounds3> boxes;
    std::vector<uint32_t> best_side;

    explicit SplitTrial(std::mt19937& rng) {
        std::uniform_real_distribution<float> half_extent(0.5f, 30.0f);
        std::vector<int> place[3];
        for (auto& order : place) {
            order.resize(kBoxes);
            std::iota(order.begin(), order.end(), 0);
            std::shuffle(order.begin(), order.end(), rng);
        }
        for (int i = 0; i < kBoxes; ++i) {
            Vec3 center, half;
            for (int a = 0; a < 3; ++a) {
                center[a] = 10.0f * float(place[a][i]);
                half[a] = half_extent(rng);
            }
            boxes.emplace_back(center - half, center + half);
        }
        std::vector<float> costs;
        std::vector<std::vector<uint32_t>> sides;
        for (int a = 0; a < 3; ++a) {
            std::vector<uint32_t> by_center(kBoxes);
            std::iota(by_center.begin(), by_center.end(), 0u);
            std::sort(by_center.begin(), by_center.end(),
                      [&](uint32_t x, uint32_t y) { return place[a][x] < place[a][y]; });
            for (int split = 1; split < kBoxes; ++split) {
                Bounds3 left, right;
                for (int k = 0; k < kBoxes; ++k) (k < split ? left : right).extend(boxes[by_center[k]]);
                costs.push_back(left.half_area() * float(split) + right.half_area() * float(kBoxes - split));
                std::vector<uint32_t> side(by_center.begin(), by_center.begin() + split);
                std::sort(side.begin(), side.end());
                sides.push_back(side);
            }
        }
        std::vector<float> sorted = costs;
        std::sort(sorted.begin(), sorted.end());
        if (sorted[1] >= sorted[0] * 1.001f)
            best_side = sides[std::min_element(costs.begin(), costs.end()) - costs.begin()];
    }

    /// Whether inner node `node` of `bvh` splits the trial's boxes into best_side and the rest.
    [[nodiscard]] bool split_is_best(const BinaryBvh& bvh, uint32_t node) const {
        std::vector<uint32_t> ids[2];
        for (uint32_t c = 0; c < 2; ++c) {
            leaves_below(bvh, bvh.nodes[node].index + c, ids[c]);
            std::sort(ids[c].begin(), ids[c].end());
        }
        return ids[0] == best_side || ids[1] == best_side;
    }
};

TEST(SahBuilder, WhereEveryPrimitiveHasABinTheRootTakesTheCheapestOfAllSplits) {
    std::mt19937 rng(2013);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const SplitTrial t(rng);
        if (t.best_side.empty()) continue;
        BvhBuildConfig config;
        config.max_leaf_size = 4;  // so that the root must split
        const BinaryBvh bvh = build_binary_bvh(t.boxes, config);
        ASSERT_FALSE(bvh.nodes[0].is_leaf());
        EXPECT_TRUE(t.split_is_best(bvh, 0)) << "trial " << trial;
        ++checked;
    }
    EXPECT_GT(checked, 150);
}

TEST(SahBuilder, AChildBinsItsOwnCentroidsAndTakesTheCheapestOfItsSplits) {
    // The trial's eight boxes next to eight small ones 100,000 away: the root parts the two
    // clusters, and the near child, binned over its own centroids (not its parent's, which
    // would put all eight in one bin), again sees every split and must take the cheapest.
    std::mt19937 rng(1987);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        SplitTrial t(rng);
        if (t.best_side.empty()) continue;
        for (int i = 0; i < SplitTrial::kBoxes; ++i) {
            const Vec3 center(1e5f + 10.0f * float(i));
            t.boxes.emplace_back(center - Vec3(1.0f), center + Vec3(1.0f));
        }
        BvhBuildConfig config;
        config.max_leaf_size = 4;
        const BinaryBvh bvh = build_binary_bvh(t.boxes, config);
        ASSERT_FALSE(bvh.nodes[0].is_leaf());
        std::vector<uint32_t> first;
        leaves_below(bvh, bvh.nodes[0].index, first);
        const uint32_t near = bvh.nodes[0].index + (*std::min_element(first.begin(), first.end()) < 8 ? 0 : 1);
        ASSERT_FALSE(bvh.nodes[near].is_leaf()) << "trial " << trial;
        EXPECT_TRUE(t.split_is_best(bvh, near)) << "trial " << trial;
        ++checked;
    }
    EXPECT_GT(checked, 150);
}

/// The union of the boxes of the primitives below `node`, checked against each node's own
/// box on the way.
Bounds3 check_boxes_below(const BinaryBvh& bvh, std::span<const Bounds3> boxes, uint32_t node, int& wrong) {
    const BvhNode& n = bvh.nodes[node];
    Bounds3 below;
    if (n.is_leaf()) {
        for (uint32_t i = n.index; i < n.index + n.count; ++i) below.extend(boxes[bvh.order[i]]);
    } else {
        below = check_boxes_below(bvh, boxes, n.index, wrong);
        below.extend(check_boxes_below(bvh, boxes, n.index + 1, wrong));
    }
    for (int a = 0; a < 3; ++a) wrong += n.bounds.lo[a] != below.lo[a] || n.bounds.hi[a] != below.hi[a];
    return below;
}

TEST(SahBuilder, EveryNodeBoxIsExactlyTheUnionOfItsPrimitivesBoxes) {
    // Enough random boxes that the top levels bin in parallel and split in parallel tasks,
    // and a hundred that share one centroid, which only median splits divide: node
    // boxes come from the bins there, from scans of the halves here, and must be tight.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f), extent(0.0f, 3.0f);
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 50000; ++i) {
        const Vec3 lo(coordinate(rng), coordinate(rng), coordinate(rng));
        boxes.emplace_back(lo, lo + Vec3(extent(rng), extent(rng), extent(rng)));
    }
    for (int i = 0; i < 100; ++i) {
        const Vec3 half(extent(rng), extent(rng), extent(rng));
        boxes.emplace_back(Vec3(500.0f) - half, Vec3(500.0f) + half);
    }
    const BinaryBvh bvh = build_binary_bvh(boxes, BvhBuildConfig{});
    int wrong = 0;
    check_boxes_below(bvh, boxes, 0, wrong);
    EXPECT_EQ(wrong, 0);
}

/// Whether the subtrees below node `a` of `x` and node `b` of `y` are the same: the same
/// boxes, splits and leaf entries (node numbers depend on which task claimed them first).
bool same_tree(const BinaryBvh& x, uint32_t a, const BinaryBvh& y, uint32_t b) {
    const BvhNode &m = x.nodes[a], &n = y.nodes[b];
    if (m.bounds.lo != n.bounds.lo || m.bounds.hi != n.bounds.hi || m.count != n.count) return false;
    if (m.is_leaf())
        return std::equal(x.order.begin() + m.index, x.order.begin() + m.index + m.count, y.order.begin() + n.index);
    return same_tree(x, m.index, y, n.index) && same_tree(x, m.index + 1, y, n.index + 1);
}

TEST(SahBuilder, BoxesComputedOnDemandGiveTheSameTreeAndEmptyOnesAreLeftOut) {
    // Several thousand boxes, every seventh empty (nothing can hit it), asked for by range
    // from several threads: the tree is the one the other boxes alone give, and its leaves
    // hold each of them exactly once.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
    std::vector<Bounds3> boxes(5000);
    for (size_t i = 0; i < boxes.size(); ++i) {
        if (i % 7 == 3) continue;  // Bounds3{} is empty
        const Vec3 lo(coordinate(rng), coordinate(rng), coordinate(rng));
        boxes[i] = Bounds3(lo, lo + Vec3(0.5f));
    }
    std::atomic<uint32_t> asked{0};
    const BinaryBvh on_demand = build_binary_bvh(
        uint32_t(boxes.size()),
        [&](uint32_t first, std::span<Bounds3> out) {
            asked += uint32_t(out.size());
            std::copy_n(boxes.begin() + first, out.size(), out.begin());
        },
        BvhBuildConfig{});
    EXPECT_EQ(asked.load(), boxes.size());
    // The same tree as the non-empty boxes alone give, their ids mapped back.
    std::vector<Bounds3> non_empty;
    std::vector<uint32_t> kept;
    for (uint32_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].empty()) {
            non_empty.push_back(boxes[i]);
            kept.push_back(i);
        }
    BinaryBvh from_array = build_binary_bvh(non_empty, BvhBuildConfig{});
    for (uint32_t& id : from_array.order) id = kept[id];
    EXPECT_TRUE(same_tree(on_demand, 0, from_array, 0));
    std::vector<uint32_t> ids;
    leaves_below(on_demand, 0, ids);
    std::sort(ids.begin(), ids.end());
    std::vector<uint32_t> expected;
    for (uint32_t i = 0; i < boxes.size(); ++i)
        if (i % 7 != 3) expected.push_back(i);
    EXPECT_EQ(ids, expected);
}

}  // namespace
}  // namespace glint
