#include "glint/accel/bvh.h"

#include <algorithm>
#include <numeric>

namespace glint {

namespace {

struct BuildItem {
    Bounds3 bounds;
    Vec3 centroid;
    uint32_t primitive;
};

class Builder {
public:
    Builder(std::vector<BuildItem>& items, const BvhBuildConfig& config, std::vector<BvhNode>& nodes)
        : items_(items), config_(config), nodes_(nodes) {}

    void build_node(uint32_t node_index, uint32_t begin, uint32_t end) {
        Bounds3 bounds, centroid_bounds;
        for (uint32_t i = begin; i < end; ++i) {
            bounds.extend(items_[i].bounds);
            centroid_bounds.extend(items_[i].centroid);
        }
        nodes_[node_index].bounds = bounds;
        const uint32_t count = end - begin;
        uint32_t mid = begin;
        if (count > 1 && find_split(begin, end, bounds, centroid_bounds, mid)) {
            const auto first_child = static_cast<uint32_t>(nodes_.size());
            nodes_.emplace_back();
            nodes_.emplace_back();
            nodes_[node_index].index = first_child;
            nodes_[node_index].count = 0;
            build_node(first_child, begin, mid);
            build_node(first_child + 1, mid, end);
            return;
        }
        nodes_[node_index].index = begin;
        nodes_[node_index].count = count;
    }

private:
    /// Binned SAH split. Returns false when a leaf is cheaper (and small enough).
    bool find_split(uint32_t begin, uint32_t end, const Bounds3& bounds, const Bounds3& centroid_bounds,
                    uint32_t& mid) {
        const uint32_t count = end - begin;
        const Vec3 extent = centroid_bounds.diagonal();
        const uint32_t bins = config_.bin_count;
        float best_cost = kInfinity;
        int best_axis = -1;
        uint32_t best_bin = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(extent[axis] > 0.0f)) continue;
            std::vector<Bounds3> bin_bounds(bins);
            std::vector<uint32_t> bin_count(bins, 0);
            const float scale = float(bins) / extent[axis];
            for (uint32_t i = begin; i < end; ++i) {
                const uint32_t b = bin_of(items_[i].centroid[axis], centroid_bounds.lo[axis], scale);
                bin_bounds[b].extend(items_[i].bounds);
                ++bin_count[b];
            }
            // Sweep from the right to get the cost of every right side.
            std::vector<float> right_cost(bins, 0.0f);
            Bounds3 acc;
            uint32_t acc_count = 0;
            for (uint32_t b = bins - 1; b > 0; --b) {
                acc.extend(bin_bounds[b]);
                acc_count += bin_count[b];
                right_cost[b] = acc.half_area() * float(acc_count);
            }
            acc = Bounds3{};
            acc_count = 0;
            for (uint32_t b = 0; b + 1 < bins; ++b) {
                acc.extend(bin_bounds[b]);
                acc_count += bin_count[b];
                const float cost = acc.half_area() * float(acc_count) + right_cost[b + 1];
                if (acc_count > 0 && acc_count < count && cost < best_cost) {
                    best_cost = cost;
                    best_axis = axis;
                    best_bin = b;
                }
            }
        }
        const float leaf_cost = bounds.half_area() * float(count);
        const float split_cost = config_.traversal_cost * bounds.half_area() + best_cost;
        if (best_axis < 0) {
            if (count <= config_.max_leaf_size) return false;
            // All centroids coincide: split the list in the middle.
            mid = begin + count / 2;
            return true;
        }
        if (split_cost >= leaf_cost && count <= config_.max_leaf_size) return false;
        const float scale = float(bins) / extent[best_axis];
        const float lo = centroid_bounds.lo[best_axis];
        auto it = std::partition(items_.begin() + begin, items_.begin() + end, [&](const BuildItem& item) {
            return bin_of(item.centroid[best_axis], lo, scale) <= best_bin;
        });
        mid = static_cast<uint32_t>(it - items_.begin());
        return true;
    }

    uint32_t bin_of(float c, float lo, float scale) const {
        const auto b = static_cast<int64_t>((c - lo) * scale);
        return static_cast<uint32_t>(std::clamp<int64_t>(b, 0, config_.bin_count - 1));
    }

    std::vector<BuildItem>& items_;
    const BvhBuildConfig& config_;
    std::vector<BvhNode>& nodes_;
};

}  // namespace

void Bvh::build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config) {
    nodes_.clear();
    order_.clear();
    std::vector<BuildItem> items;
    items.reserve(primitive_bounds.size());
    for (uint32_t i = 0; i < primitive_bounds.size(); ++i) {
        const Bounds3& b = primitive_bounds[i];
        if (b.empty()) continue;  // an empty primitive can never be hit
        items.push_back({b, b.center(), i});
    }
    if (items.empty()) return;
    nodes_.reserve(2 * items.size());
    nodes_.emplace_back();
    Builder builder(items, config, nodes_);
    builder.build_node(0, 0, static_cast<uint32_t>(items.size()));
    order_.resize(items.size());
    for (size_t i = 0; i < items.size(); ++i) order_[i] = items[i].primitive;
}

}  // namespace glint
