#pragma once
/// \file Shadow rays from the first hits of a packet of camera rays toward each delta light
/// (point, spot, directional), traced as one packet per light before the hits are shaded:
/// neighbouring points seen by neighbouring pixels send nearly parallel rays to a point
/// light, the coherent case packets serve (Wald, Slusallek et al. 2001, §4).

#include "glint/accel/ray_packet.h"
#include "glint/geometry/hit.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>

namespace glint {

class RenderScene;

/// What one lane's first hit already knows of its shadow rays toward the scene's delta
/// lights: for each light, whether the ray Whitted's direct light casts there,
/// shadow_ray(si.p, ng, ls, si.time) with the facing geometric normal ng, is blocked. Two bit
/// masks, not the rays: direct light builds that very ray with the same function from the
/// same hit, so it asks by the light's index and builds no ray at all. (Keyed by the whole
/// ray, the table cost the dragon scene 3.5 % of its CPU time, mostly a stall on reading the
/// new key back: docs/performance.md, "Store-forwarding stalls".) With the packets' rays cut
/// to 30 % of their length, `DeltaLightShadows.AnswerForTheWholeRayToTheLight` failed, and
/// so did `CameraPackets.*`, which renders every scene with packets and with single rays and
/// compares the images bit for bit.
class DeltaLightShadows {
public:
    /// Shadow rays toward lights past the first kLights in the scene's order are traced one
    /// by one.
    static constexpr uint32_t kLights = 8;

    /// Whether that shadow ray toward light `light` (its index in
    /// RenderScene::all_lights()), cast with the scene's own dielectric_shadows, is blocked;
    /// nothing if it was not traced here (not a delta light, a light under the surface, a
    /// lane without a hit).
    [[nodiscard]] std::optional<bool> occluded(uint32_t light) const {
        if (light >= kLights || !(traced_ >> light & 1)) return std::nullopt;
        return (occluded_ >> light & 1) != 0;
    }

private:
    friend std::array<DeltaLightShadows, RayPacket::kSize> trace_delta_light_shadows(
        const RenderScene&, std::span<const SurfaceInteraction>, uint32_t);
    uint32_t traced_ = 0;
    uint32_t occluded_ = 0;
};

/// For the lanes of `hit_lanes` (their hits `interactions[lane]`), the shadow ray to each
/// delta light on the side of the surface the camera ray came from, built as direct light
/// builds it (shadow_ray from the hit point and normal), traced as one packet per light.
[[nodiscard]] std::array<DeltaLightShadows, RayPacket::kSize> trace_delta_light_shadows(
    const RenderScene& scene, std::span<const SurfaceInteraction> interactions, uint32_t hit_lanes);

}  // namespace glint
