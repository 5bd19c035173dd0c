#pragma once
/// \file The benchmark ray sets of shared/docs/bench-rays.md, to the bit: primary (pinhole,
/// 1024²), shadow (any hit towards a point light) and incoherent (cosine-weighted).

#include "glint/geometry/triangle_mesh.h"

#include <cstdint>
#include <vector>

namespace glint::bench {

/// A ray as both engines take it (float32, Embree's layout of origin, tnear, direction, tfar).
struct BenchRay {
    float org[3];
    float tnear;
    float dir[3];
    float tfar;
};

/// Result of one closest-hit query: t and triangle, or prim = UINT32_MAX for a miss.
struct PrimaryHit {
    float t;
    uint32_t prim;
};

/// Camera rays, 1024×1024, row-major from the top row.
[[nodiscard]] std::vector<BenchRay> primary_rays(const MeshData& mesh, int width = 1024, int height = 1024);

struct SecondaryRays {
    std::vector<BenchRay> shadow;
    std::vector<BenchRay> incoherent;
};

/// Shadow and incoherent rays from every primary hit, in pixel order; `hits[i]` belongs to
/// `primary[i]`.
[[nodiscard]] SecondaryRays secondary_rays(const MeshData& mesh, const std::vector<BenchRay>& primary,
                                           const std::vector<PrimaryHit>& hits);

}  // namespace glint::bench
