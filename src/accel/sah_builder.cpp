#include "glint/accel/sah_builder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace glint {

namespace {

constexpr uint32_t kMaxBins = 64;
/// Ranges at least this large bin and bound their primitives with parallel reductions.
constexpr uint32_t kParallelScan = 1u << 15;
/// Subtrees at least this large are built as separate tasks.
constexpr uint32_t kParallelTask = 1u << 11;

struct PrimRef {
    Bounds3 bounds;
    uint32_t id;
    [[nodiscard]] float centroid(int axis) const { return 0.5f * (bounds.lo[axis] + bounds.hi[axis]); }
};

/// The range's box and the box of its primitives' centroids.
struct RangeBounds {
    Bounds3 bounds, centroids;
    void add(const PrimRef& r) {
        bounds.extend(r.bounds);
        centroids.extend((r.bounds.lo + r.bounds.hi) * 0.5f);
    }
    void merge(const RangeBounds& o) {
        bounds.extend(o.bounds);
        centroids.extend(o.centroids);
    }
};

struct Bins {
    Bounds3 bounds[3][kMaxBins];
    uint32_t count[3][kMaxBins] = {};
    void merge(const Bins& o, uint32_t n) {
        for (int a = 0; a < 3; ++a)
            for (uint32_t b = 0; b < n; ++b) {
                bounds[a][b].extend(o.bounds[a][b]);
                count[a][b] += o.count[a][b];
            }
    }
};

/// Maps a centroid coordinate to its bin; the scale leaves the last bin reachable only
/// by the maximum, and the clamp guards against rounding.
struct BinMapping {
    Vec3 lo, scale;
    uint32_t bins;
    BinMapping(const Bounds3& centroids, uint32_t bin_count) : lo(centroids.lo), bins(bin_count) {
        const Vec3 extent = centroids.diagonal();
        for (int a = 0; a < 3; ++a)
            scale[a] = extent[a] > 0.0f ? float(bin_count) * 0.99999f / extent[a] : 0.0f;
    }
    [[nodiscard]] uint32_t bin(float c, int axis) const {
        // Compared as floats first: a centroid far out (c - lo overflowing to inf) or NaN
        // must not reach an undefined float-to-int conversion.
        const float f = (c - lo[axis]) * scale[axis];
        if (!(f > 0.0f)) return 0;
        return f >= float(bins - 1) ? bins - 1 : static_cast<uint32_t>(f);
    }
};

class Builder {
public:
    Builder(std::vector<PrimRef>& refs, const BvhBuildConfig& config, std::vector<BvhNode>& nodes)
        : refs_(refs), config_(config), nodes_(nodes) {}

    void build(uint32_t node_index, uint32_t begin, uint32_t end, int depth) {
        const RangeBounds rb = range_bounds(begin, end);
        BvhNode& node = nodes_[node_index];
        node.bounds = rb.bounds;
        const uint32_t count = end - begin;
        uint32_t mid = 0;
        if (count == 1 || !find_split(begin, end, rb, depth, mid)) {
            node.index = begin;
            node.count = count;
            return;
        }
        const uint32_t first_child = node_count_.fetch_add(2, std::memory_order_relaxed);
        node.index = first_child;
        node.count = 0;
        if (count >= kParallelTask) {
            tbb::parallel_invoke([&] { build(first_child, begin, mid, depth + 1); },
                                 [&] { build(first_child + 1, mid, end, depth + 1); });
        } else {
            build(first_child, begin, mid, depth + 1);
            build(first_child + 1, mid, end, depth + 1);
        }
    }

    [[nodiscard]] uint32_t node_count() const { return node_count_.load(); }

private:
    [[nodiscard]] RangeBounds range_bounds(uint32_t begin, uint32_t end) const {
        auto scan = [&](uint32_t b, uint32_t e, RangeBounds acc) {
            for (uint32_t i = b; i < e; ++i) acc.add(refs_[i]);
            return acc;
        };
        if (end - begin < kParallelScan) return scan(begin, end, {});
        return tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 4096), RangeBounds{},
            [&](const tbb::blocked_range<uint32_t>& r, RangeBounds acc) { return scan(r.begin(), r.end(), acc); },
            [](RangeBounds a, const RangeBounds& b) { a.merge(b); return a; });
    }

    void fill_bins(uint32_t begin, uint32_t end, const BinMapping& map, Bins& out) const {
        auto scan = [&](uint32_t b, uint32_t e, Bins& bins) {
            for (uint32_t i = b; i < e; ++i) {
                const PrimRef& r = refs_[i];
                for (int a = 0; a < 3; ++a) {
                    const uint32_t k = map.bin(r.centroid(a), a);
                    bins.bounds[a][k].extend(r.bounds);
                    ++bins.count[a][k];
                }
            }
        };
        if (end - begin < kParallelScan) {
            scan(begin, end, out);
            return;
        }
        out = tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 8192), Bins{},
            [&](const tbb::blocked_range<uint32_t>& r, Bins acc) { scan(r.begin(), r.end(), acc); return acc; },
            [&](Bins a, const Bins& b) { a.merge(b, map.bins); return a; });
    }

    /// SAH cost of intersecting n primitives, counted in whole leaf blocks.
    [[nodiscard]] float blocks(uint32_t n) const {
        const uint32_t s = config_.leaf_block_log2;
        return float((n + (1u << s) - 1) >> s);
    }

    /// Chooses a split and partitions [begin, end) at `mid`. Returns false for a leaf.
    bool find_split(uint32_t begin, uint32_t end, const RangeBounds& rb, int depth, uint32_t& mid) {
        const uint32_t count = end - begin;
        const bool must_split = count > config_.max_leaf_size;
        if (depth < kMaxSahDepth) {
            const BinMapping map(rb.centroids, config_.bin_count);
            Bins bins;
            fill_bins(begin, end, map, bins);
            float best_cost = kInfinity;
            int best_axis = -1;
            uint32_t best_bin = 0;
            const uint32_t n_bins = map.bins;
            for (int a = 0; a < 3; ++a) {
                // Sweep from the right for every right side's cost, then from the left.
                float right_cost[kMaxBins];
                Bounds3 acc;
                uint32_t acc_count = 0;
                for (uint32_t b = n_bins - 1; b > 0; --b) {
                    acc.extend(bins.bounds[a][b]);
                    acc_count += bins.count[a][b];
                    right_cost[b] = acc.half_area() * blocks(acc_count);
                }
                acc = Bounds3{};
                acc_count = 0;
                for (uint32_t b = 0; b + 1 < n_bins; ++b) {
                    acc.extend(bins.bounds[a][b]);
                    acc_count += bins.count[a][b];
                    const float cost = acc.half_area() * blocks(acc_count) + right_cost[b + 1];
                    if (acc_count > 0 && acc_count < count && cost < best_cost) {
                        best_cost = cost;
                        best_axis = a;
                        best_bin = b;
                    }
                }
            }
            if (best_axis >= 0) {
                const float area = rb.bounds.half_area();
                const float split_cost = config_.traversal_cost * area + best_cost;
                if (!must_split && split_cost >= area * blocks(count)) return false;
                const auto first = refs_.begin() + begin;
                const auto it = std::partition(first, refs_.begin() + end, [&](const PrimRef& r) {
                    return map.bin(r.centroid(best_axis), best_axis) <= best_bin;
                });
                mid = static_cast<uint32_t>(it - refs_.begin());
                if (mid != begin && mid != end) return true;
            }
        }
        if (!must_split) return false;
        // No usable SAH split (all centroids coincide, or too deep): halve at the median
        // of the widest centroid axis.
        const int axis = max_axis(rb.centroids.diagonal());
        mid = begin + count / 2;
        std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                         [axis](const PrimRef& x, const PrimRef& y) { return x.centroid(axis) < y.centroid(axis); });
        return true;
    }

    std::vector<PrimRef>& refs_;
    const BvhBuildConfig& config_;
    std::vector<BvhNode>& nodes_;
    std::atomic<uint32_t> node_count_{1};
};

}  // namespace

BinaryBvh build_binary_bvh(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config) {
    if (config.bin_count < 2 || config.bin_count > kMaxBins)
        throw std::invalid_argument("BvhBuildConfig::bin_count must be in [2, 64]");
    if (config.max_leaf_size == 0) throw std::invalid_argument("BvhBuildConfig::max_leaf_size must be positive");
    BinaryBvh bvh;
    std::vector<PrimRef> refs;
    refs.reserve(primitive_bounds.size());
    for (uint32_t i = 0; i < primitive_bounds.size(); ++i)
        if (!primitive_bounds[i].empty()) refs.push_back({primitive_bounds[i], i});
    if (refs.empty()) return bvh;
    const auto n = static_cast<uint32_t>(refs.size());
    // A binary tree with n leaves at most has 2n - 1 nodes; children are claimed in pairs.
    bvh.nodes.resize(2 * size_t(n));
    Builder builder(refs, config, bvh.nodes);
    builder.build(0, 0, n, 0);
    bvh.nodes.resize(builder.node_count());
    bvh.nodes.shrink_to_fit();
    bvh.order.resize(n);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, n, 1u << 14), [&](const tbb::blocked_range<uint32_t>& r) {
        for (uint32_t i = r.begin(); i < r.end(); ++i) bvh.order[i] = refs[i].id;
    });
    return bvh;
}

}  // namespace glint
