#include "tinybvh_scene.h"

#define TINYBVH_IMPLEMENTATION
#include <tiny_bvh.h>

#include <string>
#include <vector>

namespace glint::bench {

struct TinyBvhScene::Impl {
    /// tinybvh keeps a view of the vertices (four floats each, three per triangle).
    std::vector<tinybvh::bvhvec4> vertices;
    tinybvh::BVH8_CPU bvh;
};

bool TinyBvhScene::available() { return true; }

std::string TinyBvhScene::version() {
    return std::to_string(TINY_BVH_VERSION_MAJOR) + "." + std::to_string(TINY_BVH_VERSION_MINOR) + "." +
           std::to_string(TINY_BVH_VERSION_SUB);
}

TinyBvhScene::TinyBvhScene(const MeshData& mesh) : impl_(std::make_unique<Impl>()) {
    impl_->vertices.reserve(mesh.indices.size());
    for (uint32_t index : mesh.indices) {
        const Vec3& p = mesh.positions[index];
        impl_->vertices.emplace_back(p.x, p.y, p.z, 0.0f);
    }
    impl_->bvh.Build(impl_->vertices.data(), static_cast<uint32_t>(mesh.indices.size() / 3));
}

TinyBvhScene::~TinyBvhScene() = default;

PrimaryHit TinyBvhScene::intersect(const BenchRay& b) const {
    tinybvh::Ray ray(tinybvh::bvhvec3(b.org[0], b.org[1], b.org[2]), tinybvh::bvhvec3(b.dir[0], b.dir[1], b.dir[2]),
                     b.tfar);
    impl_->bvh.Intersect(ray);
    // A miss leaves t at tfar; a hit is strictly closer.
    return ray.hit.t < b.tfar ? PrimaryHit{ray.hit.t, ray.hit.prim} : PrimaryHit{0.0f, UINT32_MAX};
}

bool TinyBvhScene::occluded(const BenchRay& b) const {
    const tinybvh::Ray ray(tinybvh::bvhvec3(b.org[0], b.org[1], b.org[2]),
                           tinybvh::bvhvec3(b.dir[0], b.dir[1], b.dir[2]), b.tfar);
    return impl_->bvh.IsOccluded(ray);
}

}  // namespace glint::bench
