/// RenderScene's packet queries: the top level traversed with the packet (or, for a few
/// objects, each object in turn), each object's lanes carried into its space and handed to
/// its shape's packet query.

#include "glint/accel/wide_packet_traversal.h"
#include "glint/scene/render_scene.h"

#include <bit>
#include <optional>

namespace glint {

namespace {

/// The lanes of `packet` in `lanes`, as another packet carried into an object's space by
/// `into_object(const Ray&) -> Ray` (t is kept).
template <class IntoObject>
RayPacket lanes_of(const RayPacket& packet, uint32_t lanes, const IntoObject& into_object) {
    RayPacket local;
    for (; lanes; lanes &= lanes - 1) {
        const auto lane = static_cast<uint32_t>(std::countr_zero(lanes));
        local.set(lane, into_object(packet.ray(lane)));
    }
    return local;
}

/// The time all of `lanes` share, if they do: the shadow rays of one point toward one light
/// leave at its time, so a moving object needs its placement only once for all of them.
std::optional<float> shared_time(const RayPacket& packet, uint32_t lanes) {
    if (lanes == 0) return std::nullopt;
    const float time = packet.time[std::countr_zero(lanes)];
    for (; lanes; lanes &= lanes - 1)
        if (packet.time[std::countr_zero(lanes)] != time) return std::nullopt;
    return time;
}

}  // namespace

uint32_t RenderScene::intersect_object_packet(uint32_t index, RayPacket& packet, uint32_t lanes,
                                              PacketHits& hits) const {
    const HotObject& o = objects_[index];
    uint32_t hit_lanes = 0;
    if (o.motion) {
        // Each lane at its own time: one by one.
        const uint32_t active = packet.active;
        packet.active = lanes;
        hit_lanes =
            intersect_lane_by_lane(packet, hits, [&](Ray& ray, Hit& hit) { return intersect_object(index, ray, hit); });
        packet.active = active;
    } else if (!o.transformed) {
        // In world space already (Scene::place_meshes_in_world): the shape takes the packet
        // itself, with the other lanes set aside, and shrinks the tmax of the lanes it hits.
        const uint32_t active = packet.active;
        packet.active = lanes;
        hit_lanes = o.shape->intersect_packet(packet, hits);
        packet.active = active;
    } else {
        RayPacket local = lanes_of(packet, lanes, [&](const Ray& r) { return o.object_from_world.ray(r); });
        hit_lanes = o.shape->intersect_packet(local, hits);
        for (uint32_t hit = hit_lanes; hit; hit &= hit - 1) {
            const auto lane = static_cast<uint32_t>(std::countr_zero(hit));
            packet.tmax[lane] = local.tmax[lane];
        }
    }
    for (uint32_t hit = hit_lanes; hit; hit &= hit - 1) hits.object[std::countr_zero(hit)] = index;
    return hit_lanes;
}

uint32_t RenderScene::occluded_by_object_packet(uint32_t index, const RayPacket& packet, uint32_t lanes,
                                                DielectricShadows mode) const {
    const HotObject& o = objects_[index];
    if (o.dielectric && mode == DielectricShadows::None) return 0;
    if (o.motion) {
        if (const std::optional<float> time = shared_time(packet, lanes)) {
            const Transform object_from_world = o.motion->at(*time).inverse();
            return o.shape->occluded_packet(
                lanes_of(packet, lanes, [&](const Ray& r) { return object_from_world.ray(r); }));
        }
        RayPacket moving = packet;
        moving.active = lanes;
        return occluded_lane_by_lane(moving, [&](const Ray& ray) { return occluded_by_object(index, ray, mode); });
    }
    if (o.transformed)
        return o.shape->occluded_packet(
            lanes_of(packet, lanes, [&](const Ray& r) { return o.object_from_world.ray(r); }));
    // A copy of the packet whole, not lane by lane.
    RayPacket world = packet;
    world.active = lanes;
    return o.shape->occluded_packet(world);
}

template <bool AnyHit, class Visit>
uint32_t RenderScene::visit_objects_packet(RayPacket& packet, Visit&& visit) const {
    if (top_level_.nodes().empty() || packet.active == 0) return 0;
    if (!few_objects_.empty()) {
        // A few objects: each takes the lanes (that have not hit yet, for AnyHit) and culls
        // them against its own structure.
        uint32_t hit_lanes = 0;
        for (const FewObject& few : few_objects_) {
            const uint32_t lanes = AnyHit ? packet.active & ~hit_lanes : packet.active;
            if (lanes == 0) break;
            hit_lanes |= visit(few.object, packet, lanes);
        }
        return hit_lanes;
    }
#if defined(__AVX2__)
    return traverse_packet<AnyHit>(top_level_.nodes(), packet, visit);
#else
    uint32_t hit_lanes = 0;
    for (uint32_t lanes = packet.active; lanes; lanes &= lanes - 1) {
        const auto lane = static_cast<uint32_t>(std::countr_zero(lanes));
        Ray ray = packet.ray(lane);
        auto visit_lane = [&](uint32_t object, Ray& r) {
            const bool hit = visit(object, packet, 1u << lane) != 0;
            r.tmax = packet.tmax[lane];
            return hit;
        };
        if (top_level_.traverse<AnyHit>(ray, visit_lane)) hit_lanes |= 1u << lane;
    }
    return hit_lanes;
#endif
}

uint32_t RenderScene::intersect_packet(RayPacket& packet, PacketHits& hits) const {
    return visit_objects_packet<false>(packet, [&](uint32_t object, RayPacket& p, uint32_t lanes) {
        return intersect_object_packet(object, p, lanes, hits);
    });
}

uint32_t RenderScene::occluded_packet(const RayPacket& packet, DielectricShadows mode) const {
    RayPacket scratch = packet;
    return visit_objects_packet<true>(scratch, [&](uint32_t object, RayPacket& p, uint32_t lanes) {
        return occluded_by_object_packet(object, p, lanes, mode);
    });
}

}  // namespace glint
