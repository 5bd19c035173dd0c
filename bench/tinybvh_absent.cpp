// glint-bench without a tinybvh checkout (GLINT_TINYBVH_DIR unset): no third column.
#include "tinybvh_scene.h"

#include <stdexcept>

namespace glint::bench {

struct TinyBvhScene::Impl {};

bool TinyBvhScene::available() { return false; }

std::string TinyBvhScene::version() { return {}; }

TinyBvhScene::TinyBvhScene(const MeshData& /*mesh*/) {
    throw std::logic_error("glint-bench was built without tinybvh (set GLINT_TINYBVH_DIR)");
}

TinyBvhScene::~TinyBvhScene() = default;

PrimaryHit TinyBvhScene::intersect(const BenchRay& /*ray*/) const { return {0.0f, UINT32_MAX}; }

bool TinyBvhScene::occluded(const BenchRay& /*ray*/) const { return false; }

}  // namespace glint::bench
