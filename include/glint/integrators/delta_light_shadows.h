#pragma once
/// \file Shadow rays from the first hits of a packet of camera rays toward each delta light
/// (point, spot, directional), traced as one packet per light before the hits are shaded:
/// neighbouring points seen by neighbouring pixels send nearly parallel rays to a point
/// light, the coherent case packets serve (Wald, Slusallek et al. 2001, §4).

#include "glint/accel/ray_packet.h"
#include "glint/geometry/hit.h"
#include "glint/math/ray.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace glint {

class RenderScene;

/// What one lane's first hit already knows of its shadow rays toward the scene's delta
/// lights. Keyed by the whole ray: a shading step that builds another ray (another origin
/// or direction) traces it itself, so an answer here is always the one
/// RenderScene::occluded() gives for that ray.
class DeltaLightShadows {
public:
    /// Shadow rays toward lights past the first kLights in the scene's order are traced one
    /// by one.
    static constexpr uint32_t kLights = 8;

    /// Whether `shadow`, cast toward light `light` (its index in RenderScene::all_lights())
    /// with the scene's own dielectric_shadows, is blocked; nothing if it was not traced here.
    [[nodiscard]] std::optional<bool> occluded(uint32_t light, const Ray& shadow) const;

private:
    friend std::array<DeltaLightShadows, RayPacket::kSize> trace_delta_light_shadows(
        const RenderScene&, std::span<const SurfaceInteraction>, uint32_t);
    /// A traced ray's fields, bit for bit; no initialisers, so that the render's eight
    /// lanes of them cost nothing to set up (only traced lights are written and read).
    struct RayKey {
        std::array<float, 9> fields;
        static RayKey of(const Ray& ray);
        bool operator==(const RayKey& other) const;
    };
    std::array<RayKey, kLights> rays_;
    uint32_t traced_ = 0;
    uint32_t occluded_ = 0;
};

/// For the lanes of `hit_lanes` (their hits `interactions[lane]`), the shadow ray to each
/// delta light on the side of the surface the camera ray came from, as Whitted's direct light
/// builds it (shadow_ray from the offset hit point), traced as one packet per light.
[[nodiscard]] std::array<DeltaLightShadows, RayPacket::kSize> trace_delta_light_shadows(
    const RenderScene& scene, std::span<const SurfaceInteraction> interactions, uint32_t hit_lanes);

}  // namespace glint
