#include "glint/integrators/cost_map.h"

#include "glint/scene/render_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace glint {

std::string_view cost_kind_name(CostKind kind) {
    switch (kind) {
        case CostKind::Nodes: return "BVH nodes visited";
        case CostKind::Primitives: return "primitives tested";
        case CostKind::ShadowRays: return "shadow rays";
        case CostKind::Depth: return "ray depth reached";
    }
    return "cost";
}

uint32_t PixelCost::get(CostKind kind) const {
    switch (kind) {
        case CostKind::Nodes: return nodes;
        case CostKind::Primitives: return primitives;
        case CostKind::ShadowRays: return shadow_rays;
        case CostKind::Depth: return depth;
    }
    return 0;
}

uint32_t CostMap::max(CostKind kind) const {
    uint32_t m = 0;
    for (const PixelCost& p : pixels) m = std::max(m, p.get(kind));
    return m;
}

CostMap compute_cost_map(const RenderScene& scene, const Integrator& integrator, const RenderSettings& settings,
                         const Camera& camera, uint32_t sample, const std::atomic<bool>* stop) {
    CostMap map{settings.width, settings.height, std::vector<PixelCost>(std::size_t(settings.width) * settings.height)};
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, settings.height), [&](const tbb::blocked_range<uint32_t>& rows) {
        for (uint32_t y = rows.begin(); y != rows.end(); ++y) {
            if (stop && stop->load(std::memory_order_relaxed)) return;
            for (uint32_t x = 0; x < settings.width; ++x) {
                const RayTree tree = integrator.record_sample(scene, settings, camera, x, y, sample);
                TraversalStats stats;
                PixelCost& cost = map.pixels[std::size_t(y) * settings.width + x];
                for (const RayTreeNode& node : tree.nodes()) {
                    if (node.kind == RayKind::Shadow) {
                        ++cost.shadow_rays;
                        (void)scene.occluded_counted(Ray(node.origin, node.direction, 0.0f, node.t, node.time),
                                                     scene.dielectric_shadows(), stats);
                    } else {
                        Ray ray(node.origin, node.direction, 0.0f, kInfinity, node.time);
                        Hit hit;
                        (void)scene.intersect_counted(ray, hit, stats);
                        cost.depth = std::max(cost.depth, node.depth);
                    }
                }
                cost.nodes = uint32_t(std::min<uint64_t>(stats.nodes, UINT32_MAX));
                cost.primitives = uint32_t(std::min<uint64_t>(stats.primitives, UINT32_MAX));
            }
        }
    });
    return map;
}

}  // namespace glint
