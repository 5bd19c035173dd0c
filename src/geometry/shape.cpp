#include "glint/geometry/shape.h"

#include <cmath>

namespace glint {

uint32_t Shape::intersect_packet(RayPacket& packet, PacketHits& hits) const {
    return intersect_lane_by_lane(packet, hits, [&](Ray& ray, Hit& hit) { return intersect(ray, hit); });
}

uint32_t Shape::occluded_packet(const RayPacket& packet) const {
    return occluded_lane_by_lane(packet, [&](const Ray& ray) { return occluded(ray); });
}

std::optional<ShapeSample> Shape::sample_toward(const Vec3& ref, Vec2 u, InteractionDetail detail) const {
    std::optional<ShapeSample> s = sample_area(u, detail);
    if (!s) return std::nullopt;
    s->pdf = pdf_toward(ref, s->p, s->n);
    if (!(s->pdf > 0.0f) || !std::isfinite(s->pdf)) return std::nullopt;
    return s;
}

float Shape::pdf_toward(const Vec3& ref, const Vec3& p, const Vec3& n) const {
    const float a = area();
    if (!(a > 0.0f)) return 0.0f;
    const Vec3 d = p - ref;
    const float dist2 = dot(d, d);
    const float cos_light = std::abs(dot(n, d)) / std::sqrt(dist2);
    if (cos_light == 0.0f) return 0.0f;
    return dist2 / (cos_light * a);
}

}  // namespace glint
