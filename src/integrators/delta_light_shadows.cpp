#include "glint/integrators/delta_light_shadows.h"

#include "glint/integrators/shading_point.h"
#include "glint/scene/render_scene.h"

#include <bit>

namespace glint {

std::array<DeltaLightShadows, RayPacket::kSize> trace_delta_light_shadows(
    const RenderScene& scene, std::span<const SurfaceInteraction> interactions, uint32_t hit_lanes) {
    std::array<DeltaLightShadows, RayPacket::kSize> lanes;
    const std::vector<const Light*>& lights = scene.all_lights();
    for (uint32_t i = 0; i < lights.size() && i < DeltaLightShadows::kLights; ++i) {
        if (!lights[i]->is_delta()) continue;
        RayPacket packet;
        for (uint32_t active = hit_lanes; active != 0; active &= active - 1) {
            const auto k = uint32_t(std::countr_zero(active));
            const SurfaceInteraction& si = interactions[k];
            const LightSample ls = lights[i]->sample(si.p, Vec2());
            const Vec3 ng = facing_geometric_normal(si);
            // Light from under the surface takes another shadow ray (direct light's "through").
            if (!(ls.pdf > 0.0f) || ls.radiance.is_black() || dot(ls.direction, ng) < 0.0f) continue;
            packet.set(k, shadow_ray(si.p, ng, ls, si.time));
            lanes[k].traced_ |= 1u << i;
        }
        if (packet.active == 0) continue;
        const uint32_t blocked = scene.occluded_packet(packet);
        for (uint32_t active = blocked; active != 0; active &= active - 1)
            lanes[std::countr_zero(active)].occluded_ |= 1u << i;
    }
    return lanes;
}

}  // namespace glint
