#pragma once
/// \file The reference accelerator: tests every primitive. For differential tests only.

#include "glint/math/ray.h"

#include <cstdint>

namespace glint {

/// Same traversal contract as WideBvh::traverse, each primitive 0..count-1 in order a leaf.
class BruteForce {
public:
    explicit BruteForce(uint32_t primitive_count) : count_(primitive_count) {}

    template <bool AnyHit, typename IntersectPrimitive>
    bool traverse(Ray& ray, IntersectPrimitive&& intersect_primitive) const {
        bool hit = false;
        for (uint32_t i = 0; i < count_; ++i) {
            if (intersect_primitive(i, ray)) {
                hit = true;
                if constexpr (AnyHit) return true;
            }
        }
        return hit;
    }

private:
    uint32_t count_;
};

}  // namespace glint
