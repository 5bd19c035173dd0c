#include "glint/accel/sah_builder.h"

#include "sah_binning.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <stdexcept>
#include <vector>

namespace glint {

namespace {

using namespace sah;

/// Ranges at least this large bin and bound their primitives with parallel reductions.
constexpr uint32_t kParallelScan = 1u << 15;
/// Subtrees at least this large are built as separate tasks; smaller ones by one thread
/// alone (Builder::build_alone).
constexpr uint32_t kParallelTask = 1u << 11;
/// Ranges from this size on are binned into two sets of bins (Builder::bin_range).
constexpr uint32_t kTwoBinSets = 256;

class Builder {
public:
    Builder(UninitializedArray<PrimRef>& refs, const BvhBuildConfig& config, UninitializedArray<BvhNode>& nodes)
        : refs_(refs), config_(config), nodes_(nodes) {}

    /// Builds the tree over all `count` references into node 0.
    void build_tree(uint32_t count) { build(0, 0, count, 0, range_bounds(0, count)); }

    [[nodiscard]] uint32_t node_count() const { return node_count_.load(); }

private:
    /// Where a split put its two halves, and their bounds.
    struct Children {
        uint32_t mid = 0;
        RangeBounds left, right;
    };

    /// Builds the subtree of [begin, end), whose bounds the caller knows: the root's come from
    /// a scan, a child's from its parent's split (find_split), so that every level reads its
    /// primitives twice (binning, partition) rather than three times.
    void build(uint32_t node_index, uint32_t begin, uint32_t end, int depth, const RangeBounds& rb) {
        if (end - begin < kParallelTask) {
            build_alone(node_index, begin, end, depth, rb);
            return;
        }
        Children children;
        if (!split_or_leaf(nodes_[node_index], begin, end, depth, rb, children)) return;
        const uint32_t first_child = node_count_.fetch_add(2, std::memory_order_relaxed);
        nodes_[node_index].index = first_child;
        const uint32_t mid = children.mid;
        tbb::parallel_invoke([&] { build(first_child, begin, mid, depth + 1, children.left); },
                             [&] { build(first_child + 1, mid, end, depth + 1, children.right); });
    }

    /// A subtree small enough for one thread: built into a local array (its root at 0), then
    /// placed in the shared one with a single claim of the node count. Claimed pair by pair,
    /// the shared count's cache line went back and forth between the cores at every claim:
    /// the dragon's binary tree took 28 ms on two threads instead of 23 (docs/performance.md,
    /// "Two threads, one cache line"). Sibling pairs stay adjacent: the whole local
    /// array moves by one offset.
    void build_alone(uint32_t node_index, uint32_t begin, uint32_t end, int depth, const RangeBounds& rb) {
        std::vector<BvhNode> local(1);
        local.reserve(2 * size_t(end - begin) - 1);  // the most nodes a binary tree over them has
        build_local(local, 0, begin, end, depth, rb);
        const auto claimed = static_cast<uint32_t>(local.size() - 1);
        // Local node i > 0 becomes node offset + i; the root takes `node_index`.
        const uint32_t offset = claimed == 0 ? 0 : node_count_.fetch_add(claimed, std::memory_order_relaxed) - 1;
        auto placed = [offset](BvhNode node) {
            if (!node.is_leaf()) node.index += offset;
            return node;
        };
        nodes_[node_index] = placed(local[0]);
        for (size_t i = 1; i < local.size(); ++i) nodes_[offset + i] = placed(local[i]);
    }

    /// build() within `local`: the children of each split are appended to it as a pair.
    void build_local(std::vector<BvhNode>& local, uint32_t node_index, uint32_t begin, uint32_t end, int depth,
                     const RangeBounds& rb) {
        Children children;
        if (!split_or_leaf(local[node_index], begin, end, depth, rb, children)) return;
        const auto first_child = static_cast<uint32_t>(local.size());
        local.resize(local.size() + 2);
        local[node_index].index = first_child;
        build_local(local, first_child, begin, children.mid, depth + 1, children.left);
        build_local(local, first_child + 1, children.mid, end, depth + 1, children.right);
    }

    /// Makes `node` the leaf of [begin, end), or an inner node whose split into `children`
    /// this finds (false for a leaf); the caller sets an inner node's first child.
    bool split_or_leaf(BvhNode& node, uint32_t begin, uint32_t end, int depth, const RangeBounds& rb,
                       Children& children) {
        node.bounds = rb.bounds.bounds();
        const uint32_t count = end - begin;
        if (count == 1 || !find_split(begin, end, rb, depth, children)) {
            node.index = begin;
            node.count = count;
            return false;
        }
        node.count = 0;
        return true;
    }

    [[nodiscard]] RangeBounds range_bounds(uint32_t begin, uint32_t end) const {
        // Boxes are taken by reference: passed by value, a type aligned to 32 bytes changes
        // the calling convention between builds with and without AVX (GCC's -Wpsabi note).
        auto scan = [&](uint32_t b, uint32_t e, const RangeBounds& start) {
            RangeBounds acc = start;
            for (uint32_t i = b; i < e; ++i) acc.add(refs_[i]);
            return acc;
        };
        if (end - begin < kParallelScan) return scan(begin, end, {});
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 4096), RangeBounds{},
            [&](const tbb::blocked_range<uint32_t>& r, const RangeBounds& acc) {
                return scan(r.begin(), r.end(), acc);
            },
            [](const RangeBounds& a, const RangeBounds& b) {
                RangeBounds merged = a;
                merged.merge(b);
                return merged;
            });
    }

    /// Bins primitive i into `bins`.
    void bin(uint32_t i, const BinMapping& map, Bins& bins) const {
        const PrimRef& r = refs_[i];
        const std::array<uint32_t, 4> k = map.bins_of(r);
        for (int a = 0; a < 3; ++a) {
            bins.bounds[a][k[a]].extend(r.box);
            ++bins.count[a][k[a]];
        }
    }

    /// Bins [begin, end) into `out`. From kTwoBinSets primitives on, every other one goes to
    /// a second set of bins, merged at the end: neighbours often fall in the same bin, and
    /// in one set each then waits for the other's store to its box (Embree bins two
    /// primitives at a time for the same reason).
    void bin_range(uint32_t begin, uint32_t end, const BinMapping& map, Bins& out) const {
        if (end - begin < kTwoBinSets) {
            for (uint32_t i = begin; i < end; ++i) bin(i, map, out);
            return;
        }
        Bins odd(map.bins);
        uint32_t i = begin;
        for (; i + 1 < end; i += 2) {
            bin(i, map, out);
            bin(i + 1, map, odd);
        }
        if (i < end) bin(i, map, out);
        out.merge(odd);
    }

    void fill_bins(uint32_t begin, uint32_t end, const BinMapping& map, Bins& out) const {
        if (end - begin < kParallelScan) {
            bin_range(begin, end, map, out);
            return;
        }
        out = tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 8192), Bins(map.bins),
            [&](const tbb::blocked_range<uint32_t>& r, Bins acc) {
                bin_range(r.begin(), r.end(), map, acc);
                return acc;
            },
            [&](Bins a, const Bins& b) {
                a.merge(b);
                return a;
            });
    }

    /// SAH cost of intersecting n primitives, counted in whole leaf blocks.
    [[nodiscard]] float blocks(uint32_t n) const {
        const uint32_t s = config_.leaf_block_log2;
        return float((n + (1u << s) - 1) >> s);
    }

    /// The cheapest split the bins offer: after which bin, along which axis (-1 when the
    /// centroids share one bin on every axis), at what SAH cost (both sides' area times
    /// their leaf blocks).
    struct SplitChoice {
        float cost = kInfinity;
        int axis = -1;
        uint32_t last_left_bin = 0;
    };
    [[nodiscard]] SplitChoice cheapest_split(const Bins& bins) const {
        SplitChoice best;
        for (int a = 0; a < 3; ++a) {
            // Only the bins that hold primitives: a split after an empty bin has both
            // sides of the split before it, so it costs the same and is never better.
            uint32_t used[kMaxBins];
            uint32_t n_used = 0;
            for (uint64_t m = bins.nonempty(a); m != 0; m &= m - 1) used[n_used++] = uint32_t(std::countr_zero(m));
            if (n_used < 2) continue;  // all centroids in one bin: no split along this axis
            // Sweep from the right for every right side's cost, then from the left.
            float right_cost[kMaxBins];
            Box4 acc = Box4::empty();
            uint32_t acc_count = 0;
            for (uint32_t u = n_used - 1; u > 0; --u) {
                acc.extend(bins.bounds[a][used[u]]);
                acc_count += bins.count[a][used[u]];
                right_cost[u] = acc.half_area() * blocks(acc_count);
            }
            acc = Box4::empty();
            acc_count = 0;
            for (uint32_t u = 0; u + 1 < n_used; ++u) {
                acc.extend(bins.bounds[a][used[u]]);
                acc_count += bins.count[a][used[u]];
                const float cost = acc.half_area() * blocks(acc_count) + right_cost[u + 1];
                if (cost < best.cost) best = {cost, a, used[u]};
            }
        }
        return best;
    }

    /// Whether no split of `count` primitives can cost less than their leaf, so that binning
    /// them is wasted: a split costs traversal_cost·A plus its sides' area·blocks terms, none
    /// negative, and the leaf A·blocks(count). So a range that fits one leaf block is a leaf:
    /// for triangles every leaf of two to four, 53,466 of the dragon's 107,589 calls. (Boxes
    /// with NaN coordinates, from a hostile mesh, make the heuristic compare nothing; a leaf
    /// serves them as well as a split.)
    [[nodiscard]] bool never_splits(uint32_t count) const { return blocks(count) <= config_.traversal_cost; }

    /// Chooses a split and partitions [begin, end) into `out`. Returns false for a leaf.
    bool find_split(uint32_t begin, uint32_t end, const RangeBounds& rb, int depth, Children& out) {
        const uint32_t count = end - begin;
        const bool must_split = count > config_.max_leaf_size;
        if (!must_split && never_splits(count)) return false;
        if (depth < kMaxSahDepth) {
            const BinMapping map(rb.centroids.bounds(), config_.bin_count);
            Bins bins(map.bins);
            fill_bins(begin, end, map, bins);
            const SplitChoice best = cheapest_split(bins);
            if (best.axis >= 0) {
                const float area = rb.bounds.bounds().half_area();
                const float split_cost = config_.traversal_cost * area + best.cost;
                if (!must_split && split_cost >= area * blocks(count)) return false;
                const uint64_t used = bins.nonempty(best.axis);
                const uint64_t left_bins = used & (~uint64_t(0) >> (63 - best.last_left_bin));
                out.left.bounds = bins.union_of(best.axis, left_bins);
                out.right.bounds = bins.union_of(best.axis, used & ~left_bins);
                out.mid =
                    partition(begin, end, map, best.axis, best.last_left_bin, out.left.centroids, out.right.centroids);
                if (out.mid != begin && out.mid != end) return true;
            }
        }
        if (!must_split) return false;
        // No usable SAH split (all centroids coincide, or too deep): halve at the median
        // of the widest centroid axis.
        const int axis = max_axis(rb.centroids.bounds().diagonal());
        out.mid = begin + count / 2;
        std::nth_element(refs_.begin() + begin, refs_.begin() + out.mid, refs_.begin() + end,
                         [axis](const PrimRef& x, const PrimRef& y) { return x.centroid(axis) < y.centroid(axis); });
        out.left = range_bounds(begin, out.mid);
        out.right = range_bounds(out.mid, end);
        return true;
    }

    /// Moves the primitives of [begin, end) whose bin along `axis` is at most `last_left_bin`
    /// to the front and returns where the rest start; gathers both sides' centroid boxes on
    /// the way. The boxes of the bins already give both sides' bounds, so the children need
    /// no scan of their own. Branch-free (Lomuto's scheme, swapping every primitive): which
    /// side a primitive falls on is a coin toss near the root, and the branches of
    /// std::partition mispredicted there about every other primitive.
    uint32_t partition(uint32_t begin, uint32_t end, const BinMapping& map, int axis, uint32_t last_left_bin,
                       Box4& left_centroids, Box4& right_centroids) {
        PrimRef* refs = refs_.data();
        // Extended in locals: through the references, which the stores to `refs` might alias,
        // GCC kept them in memory, a store and a load on every primitive's path.
        Box4 left_box = left_centroids, right_box = right_centroids;
        uint32_t mid = begin;
        for (uint32_t i = begin; i < end; ++i) {
            alignas(16) float c[4];
            refs[i].centroid(c);
            const bool left = map.bins_of_centroid(c)[axis] <= last_left_bin;
            left_box.extend_point_if(c, left);
            right_box.extend_point_if(c, !left);
            swap_refs(refs[i], refs[mid]);
            mid += left;
        }
        left_centroids = left_box;
        right_centroids = right_box;
        return mid;
    }

    UninitializedArray<PrimRef>& refs_;
    const BvhBuildConfig& config_;
    UninitializedArray<BvhNode>& nodes_;
    /// On a cache line of its own: the members above are read in every loop of every thread,
    /// and each claim would otherwise take their line away from the other core (32 ms
    /// instead of 28 for the dragon's binary tree on two threads).
    alignas(64) std::atomic<uint32_t> node_count_{1};
};

/// The references to all primitives whose bounds are not empty, in index order. Filled in
/// parallel straight from `bounds`, without an array of every primitive's box.
UninitializedArray<PrimRef> primitive_refs(uint32_t count, const PrimitiveBounds& bounds) {
    constexpr uint32_t kChunk = 1024;
    UninitializedArray<PrimRef> refs(count);
    std::atomic<bool> some_empty{false};
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, kChunk), [&](const tbb::blocked_range<uint32_t>& r) {
        Bounds3 boxes[kChunk];
        for (uint32_t first = r.begin(); first < r.end(); first += kChunk) {
            const uint32_t n = std::min(kChunk, r.end() - first);
            bounds(first, std::span(boxes, n));
            for (uint32_t i = 0; i < n; ++i) {
                if (boxes[i].empty()) some_empty.store(true, std::memory_order_relaxed);
                refs[first + i] = PrimRef(boxes[i], first + i);
            }
        }
    });
    // Empty boxes (NaN vertices) are rare: removed in one ordered pass when there are any.
    if (some_empty.load())
        refs.erase(std::remove_if(refs.begin(), refs.end(), [](const PrimRef& r) { return r.box.bounds().empty(); }),
                   refs.end());
    return refs;
}

}  // namespace

PrimitiveBounds bounds_copied_from(std::span<const Bounds3> boxes) {
    return [boxes](uint32_t first, std::span<Bounds3> out) {
        std::copy_n(boxes.begin() + first, out.size(), out.begin());
    };
}

BinaryBvh build_binary_bvh(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config) {
    return build_binary_bvh(static_cast<uint32_t>(primitive_bounds.size()), bounds_copied_from(primitive_bounds),
                            config);
}

BinaryBvh build_binary_bvh(uint32_t count, const PrimitiveBounds& bounds, const BvhBuildConfig& config) {
    if (config.bin_count < 2 || config.bin_count > kMaxBins)
        throw std::invalid_argument("BvhBuildConfig::bin_count must be in [2, 64]");
    if (config.max_leaf_size == 0) throw std::invalid_argument("BvhBuildConfig::max_leaf_size must be positive");
    BinaryBvh bvh;
    UninitializedArray<PrimRef> refs = primitive_refs(count, bounds);
    if (refs.empty()) return bvh;
    const auto n = static_cast<uint32_t>(refs.size());
    // A binary tree with n leaves at most has 2n - 1 nodes; children are claimed in pairs.
    // Left unwritten (UninitializedArray): the builder writes each node it claims, on
    // the thread that claims it, and leaves of four primitives claim about a quarter of
    // them, so most of the array is never touched (zeroing it was 40 MB of page faults on
    // one thread for the full dragon).
    bvh.nodes.resize(2 * size_t(n));
    Builder builder(refs, config, bvh.nodes);
    builder.build_tree(n);
    // Not shrunk to fit: the binary tree lives only until the collapse, and a shrink would
    // copy it into freshly faulted pages.
    bvh.nodes.resize(builder.node_count());
    bvh.order.resize(n);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, n, 1u << 14), [&](const tbb::blocked_range<uint32_t>& r) {
        for (uint32_t i = r.begin(); i < r.end(); ++i) bvh.order[i] = refs[i].id();
    });
    return bvh;
}

}  // namespace glint
