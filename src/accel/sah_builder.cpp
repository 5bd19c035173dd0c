#include "glint/accel/sah_builder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstring>
#include <stdexcept>

namespace glint {

namespace {

constexpr uint32_t kMaxBins = 64;
/// Ranges at least this large bin and bound their primitives with parallel reductions.
constexpr uint32_t kParallelScan = 1u << 15;
/// Subtrees at least this large are built as separate tasks.
constexpr uint32_t kParallelTask = 1u << 11;

/// A box as two rows of four floats (x, y, z and a spare lane), so that extending one by
/// another is one min and one max of four lanes where Bounds3 takes six scalar steps:
/// binning is most of the build (Wald 2007 bins with SSE the same way). Lane by lane the
/// results are Bounds3's bit for bit (min and max keep the same operand on ties), so the
/// tree is the one the scalar code built.
struct alignas(16) Box4 {
    float lo[4];
    float hi[4];

    /// The empty box (lo > hi), which extending by anything makes that thing.
    [[nodiscard]] static Box4 empty() {
        return {{kInfinity, kInfinity, kInfinity, kInfinity}, {-kInfinity, -kInfinity, -kInfinity, -kInfinity}};
    }

    void extend(const Box4& b) { extend_lanes(b.lo, b.hi); }
    /// Extend by the point in the first three lanes of `p`.
    void extend_point(const float* p) { extend_lanes(p, p); }
    [[nodiscard]] Bounds3 bounds() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
    /// Bounds3::half_area of a box that is not empty, by the same sum of products in the same
    /// order, without the conversion to Bounds3 and the emptiness test the split search paid
    /// for each bin (the trees it builds hash the same as before, docs/performance.md).
    [[nodiscard]] float half_area() const {
        alignas(16) float d[4];
#if defined(__SSE2__)
        _mm_store_ps(d, _mm_sub_ps(_mm_load_ps(hi), _mm_load_ps(lo)));
#else
        for (int i = 0; i < 4; ++i) d[i] = hi[i] - lo[i];
#endif
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    }

private:
    void extend_lanes(const float* l, const float* h) {
#if defined(__SSE2__)
        // minps(a, b) is a < b ? a : b, so minps(new, old) is std::min(old, new).
        _mm_store_ps(lo, _mm_min_ps(_mm_loadu_ps(l), _mm_load_ps(lo)));
        _mm_store_ps(hi, _mm_max_ps(_mm_loadu_ps(h), _mm_load_ps(hi)));
#else
        for (int i = 0; i < 4; ++i) {
            lo[i] = std::min(lo[i], l[i]);
            hi[i] = std::max(hi[i], h[i]);
        }
#endif
    }
};

/// A primitive's box and index in 32 bytes, the index in the spare lane of `box.lo` (as
/// Embree's PrimRef keeps it); that lane's min and max in the bins mean nothing, and no
/// arithmetic reads it (an index's bits are mostly a denormal float, which would slow an
/// addition down many times over).
struct PrimRef {
    Box4 box;
    PrimRef(const Bounds3& b, uint32_t id) : box() {
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = b.lo[a];
            box.hi[a] = b.hi[a];
        }
        std::memcpy(&box.lo[3], &id, sizeof id);
        box.hi[3] = 0.0f;
    }
    [[nodiscard]] uint32_t id() const {
        uint32_t id = 0;
        std::memcpy(&id, &box.lo[3], sizeof id);
        return id;
    }
    [[nodiscard]] float centroid(int axis) const { return 0.5f * (box.lo[axis] + box.hi[axis]); }
    /// The centroid in the first three lanes, 0 in the fourth.
    void centroid(float* out) const {
#if defined(__SSE2__)
        const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
        const __m128 lo = _mm_and_ps(_mm_load_ps(box.lo), xyz);
        _mm_store_ps(out, _mm_mul_ps(_mm_add_ps(lo, _mm_load_ps(box.hi)), _mm_set1_ps(0.5f)));
#else
        for (int i = 0; i < 3; ++i) out[i] = 0.5f * (box.lo[i] + box.hi[i]);
        out[3] = 0.0f;
#endif
    }
};
static_assert(sizeof(PrimRef) == 32);

/// The range's box and the box of its primitives' centroids.
struct RangeBounds {
    Box4 bounds = Box4::empty(), centroids = Box4::empty();
    void add(const PrimRef& r) {
        bounds.extend(r.box);
        alignas(16) float c[4];
        r.centroid(c);
        centroids.extend_point(c);
    }
    void merge(const RangeBounds& o) {
        bounds.extend(o.bounds);
        centroids.extend(o.centroids);
    }
};

/// The bins of the three axes. Only the first `used` of each are set: most ranges are
/// small, and clearing all 64 bins of every axis for each was a tenth of the build. Counts
/// are set up to the next multiple of four, so that nonempty() reads them four at a time.
class Bins {
public:
    explicit Bins(uint32_t used) : used_(used) {
        for (int a = 0; a < 3; ++a) {
            for (uint32_t b = 0; b < used; ++b) {
                bounds[a][b] = Box4::empty();
                count[a][b] = 0;
            }
            for (uint32_t b = used; b < counted(); ++b) count[a][b] = 0;
        }
    }
    Bins(const Bins& o) : used_(o.used_) { *this = o; }
    Bins& operator=(const Bins& o) {
        used_ = o.used_;
        for (int a = 0; a < 3; ++a) {
            std::copy_n(o.bounds[a], used_, bounds[a]);
            std::copy_n(o.count[a], counted(), count[a]);
        }
        return *this;
    }
    void merge(const Bins& o) {
        for (int a = 0; a < 3; ++a)
            for (uint32_t b = 0; b < used_; ++b) {
                bounds[a][b].extend(o.bounds[a][b]);
                count[a][b] += o.count[a][b];
            }
    }

    /// Bit b is set when bin b of `axis` holds primitives: the sweep visits only those, and
    /// finding them four counts at a time was a sixth of the split search when it tested
    /// every bin of every node one by one (most nodes hold a few primitives).
    [[nodiscard]] uint64_t nonempty(int axis) const {
        uint64_t mask = 0;
#if defined(__SSE2__)
        for (uint32_t b = 0; b < used_; b += 4) {
            const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(count[axis] + b));
            const int empty = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(c, _mm_setzero_si128())));
            mask |= uint64_t(~empty & 0xf) << b;
        }
#else
        for (uint32_t b = 0; b < used_; ++b) mask |= uint64_t(count[axis][b] != 0) << b;
#endif
        return mask;
    }

    // Boxes are left uninitialised past `used`, counts past counted() (copying them would
    // read indeterminate values).
    Box4 bounds[3][kMaxBins];
    alignas(16) uint32_t count[3][kMaxBins];

private:
    /// How many counts are set: `used` rounded up to a multiple of four.
    [[nodiscard]] uint32_t counted() const { return (used_ + 3) & ~3u; }

    uint32_t used_;
};

/// Maps a centroid coordinate to its bin; the scale leaves the last bin reachable only
/// by the maximum, and the clamp guards against rounding.
struct BinMapping {
    alignas(16) float lo[4] = {};
    alignas(16) float scale[4] = {};
    uint32_t bins;
    BinMapping(const Bounds3& centroids, uint32_t bin_count) : bins(bin_count) {
        const Vec3 extent = centroids.diagonal();
        for (int a = 0; a < 3; ++a) {
            lo[a] = centroids.lo[a];
            scale[a] = extent[a] > 0.0f ? float(bin_count) * 0.99999f / extent[a] : 0.0f;
        }
    }
    /// The bins of a primitive's centroid along the three axes (the fourth is 0), the same
    /// numbers for binning and for the partition that follows it.
    [[nodiscard]] std::array<uint32_t, 4> bins_of(const PrimRef& r) const {
        alignas(16) float centroid[4];
        r.centroid(centroid);
        alignas(16) std::array<uint32_t, 4> out;
#if defined(__SSE2__)
        const __m128 f = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(centroid), _mm_load_ps(lo)), _mm_load_ps(scale));
        // Clamped as floats first (maxps(f, 0) is 0 for NaN), so that a centroid far out
        // or NaN never reaches an undefined float-to-int conversion.
        const __m128 clamped = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(float(bins - 1)));
        _mm_store_si128(reinterpret_cast<__m128i*>(out.data()), _mm_cvttps_epi32(clamped));
#else
        for (int a = 0; a < 4; ++a) {
            const float f = (centroid[a] - lo[a]) * scale[a];
            out[a] = !(f > 0.0f) ? 0 : f >= float(bins - 1) ? bins - 1 : static_cast<uint32_t>(f);
        }
#endif
        return out;
    }
};

class Builder {
public:
    Builder(std::vector<PrimRef>& refs, const BvhBuildConfig& config, UninitializedArray<BvhNode>& nodes)
        : refs_(refs), config_(config), nodes_(nodes) {}

    void build(uint32_t node_index, uint32_t begin, uint32_t end, int depth) {
        const RangeBounds rb = range_bounds(begin, end);
        BvhNode& node = nodes_[node_index];
        node.bounds = rb.bounds.bounds();
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
                const std::array<uint32_t, 4> k = map.bins_of(r);
                for (int a = 0; a < 3; ++a) {
                    bins.bounds[a][k[a]].extend(r.box);
                    ++bins.count[a][k[a]];
                }
            }
        };
        if (end - begin < kParallelScan) {
            scan(begin, end, out);
            return;
        }
        out = tbb::parallel_reduce(
            tbb::blocked_range<uint32_t>(begin, end, 8192), Bins(map.bins),
            [&](const tbb::blocked_range<uint32_t>& r, Bins acc) {
                scan(r.begin(), r.end(), acc);
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

    /// Chooses a split and partitions [begin, end) at `mid`. Returns false for a leaf.
    bool find_split(uint32_t begin, uint32_t end, const RangeBounds& rb, int depth, uint32_t& mid) {
        const uint32_t count = end - begin;
        const bool must_split = count > config_.max_leaf_size;
        if (depth < kMaxSahDepth) {
            const BinMapping map(rb.centroids.bounds(), config_.bin_count);
            Bins bins(map.bins);
            fill_bins(begin, end, map, bins);
            float best_cost = kInfinity;
            int best_axis = -1;
            uint32_t best_bin = 0;
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
                    if (cost < best_cost) {
                        best_cost = cost;
                        best_axis = a;
                        best_bin = used[u];
                    }
                }
            }
            if (best_axis >= 0) {
                const float area = rb.bounds.bounds().half_area();
                const float split_cost = config_.traversal_cost * area + best_cost;
                if (!must_split && split_cost >= area * blocks(count)) return false;
                const auto first = refs_.begin() + begin;
                const auto it = std::partition(first, refs_.begin() + end,
                                               [&](const PrimRef& r) { return map.bins_of(r)[best_axis] <= best_bin; });
                mid = static_cast<uint32_t>(it - refs_.begin());
                if (mid != begin && mid != end) return true;
            }
        }
        if (!must_split) return false;
        // No usable SAH split (all centroids coincide, or too deep): halve at the median
        // of the widest centroid axis.
        const int axis = max_axis(rb.centroids.bounds().diagonal());
        mid = begin + count / 2;
        std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                         [axis](const PrimRef& x, const PrimRef& y) { return x.centroid(axis) < y.centroid(axis); });
        return true;
    }

    std::vector<PrimRef>& refs_;
    const BvhBuildConfig& config_;
    UninitializedArray<BvhNode>& nodes_;
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
        if (!primitive_bounds[i].empty()) refs.emplace_back(primitive_bounds[i], i);
    if (refs.empty()) return bvh;
    const auto n = static_cast<uint32_t>(refs.size());
    // A binary tree with n leaves at most has 2n - 1 nodes; children are claimed in pairs.
    // Left unwritten (UninitializedArray): the builder writes each node it claims, on
    // the thread that claims it, and leaves of four primitives claim about a quarter of
    // them, so most of the array is never touched (zeroing it was 40 MB of page faults on
    // one thread for the full dragon).
    bvh.nodes.resize(2 * size_t(n));
    Builder builder(refs, config, bvh.nodes);
    builder.build(0, 0, n, 0);
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
