#pragma once
/// \file Eight rays traced together: coherent rays (a row of camera rays, shadow rays from
/// neighbouring points toward one point light) share most of their way through a BVH, so
/// one traversal tests each box against all eight at once with SIMD across the rays
/// (Wald, Slusallek et al. 2001, "Interactive Rendering with Coherent Ray Tracing"; Embree's
/// rtcIntersect8/rtcOccluded8 take the same eight-lane layout).

#include "glint/geometry/hit.h"
#include "glint/math/constants.h"
#include "glint/math/ray.h"

#include <array>
#include <bit>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace glint {

/// Eight rays as structure of arrays. Lanes outside `active` are not rays: queries never
/// read or write them. Closest-hit queries shrink tmax as Ray::tmax does.
struct alignas(32) RayPacket {
    static constexpr uint32_t kSize = 8;
    static constexpr uint32_t kAllLanes = 0xffu;
    float origin[3][kSize]{};
    float direction[3][kSize]{};
    float tmin[kSize]{};
    float tmax[kSize]{};
    /// Ray::time of each lane (motion blur).
    float time[kSize]{};
    uint32_t active = 0;

    /// Puts `ray` in `lane` and marks the lane active.
    void set(uint32_t lane, const Ray& ray) {
        for (int a = 0; a < 3; ++a) {
            origin[a][lane] = ray.origin[a];
            direction[a][lane] = ray.direction[a];
        }
        tmin[lane] = ray.tmin;
        tmax[lane] = ray.tmax;
        time[lane] = ray.time;
        active |= 1u << lane;
    }
    /// The ray in `lane`, with its current tmax.
    [[nodiscard]] Ray ray(uint32_t lane) const {
        return Ray(Vec3(origin[0][lane], origin[1][lane], origin[2][lane]),
                   Vec3(direction[0][lane], direction[1][lane], direction[2][lane]), tmin[lane], tmax[lane],
                   time[lane]);
    }
};

/// One value per lane, lane k's made by `make(k)` in the array itself (the elements'
/// copy elision). Assigned from a temporary instead, a fresh struct comes back through wide
/// loads of the narrower stores just made, which the CPU cannot forward: a stall that cost
/// the render's camera rays and first hits more than making them (docs/performance.md).
template <class Make>
[[nodiscard]] auto per_lane(const Make& make) {
    using Value = std::invoke_result_t<const Make&, uint32_t>;
    return [&]<std::size_t... K>(std::index_sequence<K...>) {
        return std::array<Value, RayPacket::kSize>{make(uint32_t(K))...};
    }
    (std::make_index_sequence<RayPacket::kSize>());
}

/// Closest hits of a packet's lanes, as Hit holds them for one ray (t, primitive, the
/// shape's parameters, and, from the scene's queries, the object); a lane without a hit
/// keeps what it held.
struct alignas(32) PacketHits {
    float t[RayPacket::kSize];
    float u[RayPacket::kSize];
    float v[RayPacket::kSize];
    uint32_t primitive[RayPacket::kSize];
    uint32_t object[RayPacket::kSize];

    /// Lane `lane`'s hit as a Hit.
    [[nodiscard]] Hit hit(uint32_t lane) const {
        Hit h;
        h.t = t[lane];
        h.object = object[lane];
        h.primitive = primitive[lane];
        h.u = u[lane];
        h.v = v[lane];
        return h;
    }
    /// Stores `h` (all but the object) as lane `lane`'s hit.
    void set(uint32_t lane, const Hit& h) {
        t[lane] = h.t;
        primitive[lane] = h.primitive;
        u[lane] = h.u;
        v[lane] = h.v;
    }
};

/// A packet query answered lane by lane with a single-ray query, `intersect(Ray&, Hit&) ->
/// bool` (which shrinks the ray's tmax on a hit): the fall-back where a packet gains nothing
/// (an analytic shape, a moving object, a CPU without AVX2). Returns the lanes that hit.
template <class Intersect>
uint32_t intersect_lane_by_lane(RayPacket& packet, PacketHits& hits, Intersect&& intersect) {
    uint32_t hit_lanes = 0;
    for (uint32_t lanes = packet.active; lanes; lanes &= lanes - 1) {
        const auto lane = static_cast<uint32_t>(std::countr_zero(lanes));
        Ray ray = packet.ray(lane);
        Hit hit;
        if (!intersect(ray, hit)) continue;
        packet.tmax[lane] = ray.tmax;
        hits.set(lane, hit);
        hits.object[lane] = hit.object;
        hit_lanes |= 1u << lane;
    }
    return hit_lanes;
}

/// The same for any-hit queries, `occluded(const Ray&) -> bool`.
template <class Occluded>
uint32_t occluded_lane_by_lane(const RayPacket& packet, Occluded&& occluded) {
    uint32_t hit_lanes = 0;
    for (uint32_t lanes = packet.active; lanes; lanes &= lanes - 1) {
        const auto lane = static_cast<uint32_t>(std::countr_zero(lanes));
        if (occluded(packet.ray(lane))) hit_lanes |= 1u << lane;
    }
    return hit_lanes;
}

}  // namespace glint
