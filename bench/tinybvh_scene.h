#pragma once
/// \file tinybvh's `BVH8_CPU` on the same mesh: the yardstick issue 13 names beside Embree
/// (jbikker/tinybvh; 8-wide, AVX2, binned SAH, Möller–Trumbore leaves on precomputed edges).
/// Measured only when CMake is given a tinybvh checkout (GLINT_TINYBVH_DIR): tinybvh is not a
/// Debian package, and its code stays in the user's checkout. tinybvh_scene.cpp wraps it;
/// without a checkout, tinybvh_absent.cpp stands in and available() is false.

#include "bench_rays.h"

#include <memory>
#include <string>

namespace glint::bench {

/// One `tinybvh::BVH8_CPU` over a copy of the mesh's triangles, queried as a tinybvh user
/// does (`Ray(origin, direction, tfar)`, `Intersect`, `IsOccluded`). Its build runs tinybvh's
/// own threads, so its time is not comparable with the thread-limited builds and is not
/// reported.
class TinyBvhScene {
public:
    /// Whether this glint-bench was built with tinybvh.
    [[nodiscard]] static bool available();
    /// The tinybvh release measured ("1.9.0", from its TINY_BVH_VERSION_* macros): issue 13
    /// names 1.6.7, and releases differ in build and kernels. Empty when not available().
    [[nodiscard]] static std::string version();

    explicit TinyBvhScene(const MeshData& mesh);
    ~TinyBvhScene();
    TinyBvhScene(const TinyBvhScene&) = delete;
    TinyBvhScene& operator=(const TinyBvhScene&) = delete;

    /// Closest hit (BVH8_CPU::Intersect). tinybvh's rays start at t = 0: the benchmark's do.
    [[nodiscard]] PrimaryHit intersect(const BenchRay& ray) const;
    /// Any hit (BVH8_CPU::IsOccluded).
    [[nodiscard]] bool occluded(const BenchRay& ray) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace glint::bench
