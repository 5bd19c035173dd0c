#pragma once
/// \file What each pixel costs, for the viewer's heatmaps: the rays of one sample of each
/// pixel (recorded as `glint explain` records them) traced again through counting traversals
/// (accel/traversal_count.h). The render itself never counts.

#include "glint/integrators/integrator.h"
#include "glint/scene/camera.h"

#include <atomic>
#include <cstdint>
#include <string_view>
#include <vector>

namespace glint {

enum class CostKind : uint8_t {
    Nodes,       ///< BVH nodes visited, top level and meshes
    Primitives,  ///< triangles and analytic shapes tested
    ShadowRays,  ///< shadow rays cast
    Depth,       ///< deepest reflection, refraction or bounce reached (0: the camera ray only)
};

[[nodiscard]] std::string_view cost_kind_name(CostKind kind);

struct PixelCost {
    uint32_t nodes = 0, primitives = 0, shadow_rays = 0, depth = 0;
    [[nodiscard]] uint32_t get(CostKind kind) const;
};

struct CostMap {
    uint32_t width = 0, height = 0;
    std::vector<PixelCost> pixels;
    [[nodiscard]] const PixelCost& at(uint32_t x, uint32_t y) const { return pixels[std::size_t(y) * width + x]; }
    [[nodiscard]] uint32_t max(CostKind kind) const;
};

/// The cost of sample `sample` of every pixel of a `settings.width`×`settings.height` image
/// seen through `camera`. Returns early (a partial map) once *stop is set.
[[nodiscard]] CostMap compute_cost_map(const RenderScene& scene, const Integrator& integrator,
                                       const RenderSettings& settings, const Camera& camera, uint32_t sample = 0,
                                       const std::atomic<bool>* stop = nullptr);

}  // namespace glint
