#pragma once
/// \file Binary bounding volume hierarchy over abstract primitives.
///
/// The BVH knows nothing of shapes: it is built from a span of primitive bounds and
/// traversed with a leaf callback that intersects one primitive (madmann91/bvh style).
/// Scenes use it over objects (the top level); triangle meshes use the 8-wide
/// `TriangleBvh` (see wide_bvh.h), which is much faster for many small primitives.

#include "glint/accel/sah_builder.h"
#include "glint/accel/traversal_count.h"
#include "glint/math/bounds3.h"
#include "glint/math/ray.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace glint {

class Bvh {
public:
    /// Binned SAH build (see build_binary_bvh); empty and degenerate bounds are allowed.
    void build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config = {});

    /// Visit leaves front to back. `intersect_primitive(uint32_t primitive, Ray& ray) -> bool`
    /// tests one primitive, shrinks ray.tmax on a closer hit and returns true if it hit.
    /// With AnyHit the traversal stops at the first hit. Returns whether anything was hit.
    template <bool AnyHit, typename IntersectPrimitive, typename Count = NoTraversalCount>
    bool traverse(Ray& ray, IntersectPrimitive&& intersect_primitive, const Count& count = {}) const;

    /// Node 0 is the root; empty when there is nothing to hit.
    [[nodiscard]] std::span<const BvhNode> nodes() const { return nodes_; }
    /// Leaf entries in traversal order, mapping to the caller's primitive indices.
    [[nodiscard]] std::span<const uint32_t> primitive_order() const { return order_; }
    /// Box of all primitives.
    [[nodiscard]] Bounds3 bounds() const { return nodes_.empty() ? Bounds3{} : nodes_[0].bounds; }
    /// Bytes of nodes and primitive order.
    [[nodiscard]] std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(BvhNode) + order_.size() * sizeof(uint32_t);
    }

private:
    std::vector<BvhNode> nodes_;
    std::vector<uint32_t> order_;
};

template <bool AnyHit, typename IntersectPrimitive, typename Count>
bool Bvh::traverse(Ray& ray, IntersectPrimitive&& intersect_primitive, const Count& count) const {
    if (nodes_.empty()) return false;
    const Vec3 inv_dir(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z);
    // Every inner node on the way down pushes at most one child, and no leaf lies deeper
    // than kMaxBinaryBvhDepth.
    constexpr int kStackSize = kMaxBinaryBvhDepth;
    uint32_t stack[kStackSize];
    int top = 0;
    bool hit = false;
    float t0, t1;
    if (!nodes_[0].bounds.intersect(ray.origin, inv_dir, ray.tmin, ray.tmax, t0, t1)) return false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes_[current];
        count.node();
        if (node.is_leaf()) {
            for (uint32_t i = node.index; i < node.index + node.count; ++i) {
                if (intersect_primitive(order_[i], ray)) {
                    hit = true;
                    if constexpr (AnyHit) return true;
                }
            }
        } else {
            const uint32_t left = node.index, right = node.index + 1;
            float l_enter, l_exit, r_enter, r_exit;
            const bool hit_left =
                nodes_[left].bounds.intersect(ray.origin, inv_dir, ray.tmin, ray.tmax, l_enter, l_exit);
            const bool hit_right =
                nodes_[right].bounds.intersect(ray.origin, inv_dir, ray.tmin, ray.tmax, r_enter, r_exit);
            if (hit_left && hit_right) {
                const bool left_first = l_enter <= r_enter;
                stack[top++] = left_first ? right : left;
                current = left_first ? left : right;
                continue;
            }
            if (hit_left) {
                current = left;
                continue;
            }
            if (hit_right) {
                current = right;
                continue;
            }
        }
        if (top == 0) break;
        current = stack[--top];
    }
    return hit;
}

}  // namespace glint
