#pragma once
/// \file Embree 3 on the same mesh: the reference glint-bench compares Glint against.

#include "bench_rays.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

namespace glint::bench {

/// An Embree device limited to `threads` build threads, with one triangle geometry built
/// with RTC_BUILD_QUALITY_HIGH over the caller's arrays (shared, so not counted as memory).
/// `extra_config` is appended to the device's configuration string (rtcNewDevice's syntax,
/// e.g. "isa=avx2" to pin Embree's kernels to an instruction set).
class EmbreeScene {
public:
    EmbreeScene(const MeshData& mesh, int threads, const std::string& extra_config = {});
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /// Builds (rtcCommitScene) and returns the wall time in milliseconds.
    double build();
    /// Bytes Embree allocated for the scene and kept after the build (memory monitor).
    [[nodiscard]] std::size_t bytes() const { return static_cast<std::size_t>(retained_); }

    /// Closest hit (rtcIntersect1).
    [[nodiscard]] PrimaryHit intersect(const BenchRay& ray) const;
    /// Any hit (rtcOccluded1).
    [[nodiscard]] bool occluded(const BenchRay& ray) const;
    /// Closest hits of up to eight rays as one packet (rtcIntersect8, coherent context).
    void intersect8(const BenchRay* rays, int count, PrimaryHit* out) const;
    /// Any hits of up to eight rays as one packet (rtcOccluded8, coherent context); an
    /// occluded ray gets prim 0, a free one UINT32_MAX.
    void occluded8(const BenchRay* rays, int count, PrimaryHit* out) const;

private:
    static bool monitor(void* self, ssize_t bytes, bool post);

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<Vec3> vertices_;
    std::atomic<long long> allocated_{0};
    long long retained_ = 0;
};

}  // namespace glint::bench
