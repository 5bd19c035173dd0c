#include "glint/accel/bvh.h"

namespace glint {

void Bvh::build(std::span<const Bounds3> primitive_bounds, const BvhBuildConfig& config) {
    BinaryBvh built = build_binary_bvh(primitive_bounds, config);
    nodes_ = std::move(built.nodes);
    order_ = std::move(built.order);
}

}  // namespace glint
