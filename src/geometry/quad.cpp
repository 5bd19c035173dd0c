#include "glint/geometry/quad.h"

#include "glint/scene_format/param_table.h"

#include <cmath>
#include <stdexcept>

namespace glint {

Quad::Quad(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v)
    : corner_(corner), edge_u_(edge_u), edge_v_(edge_v) {
    const Vec3 n = cross(edge_u, edge_v);
    if (!(length(n) > 0.0f) || !is_finite(n) || !is_finite(corner))
        throw std::invalid_argument("quad edges must be finite, non-zero and not parallel");
    normal_ = normalize(n);
    cross_uv_ = n;
    inv_cross_uv2_ = 1.0f / dot(n, n);
    area_ = length(n);
}

std::optional<ShapeSample> Quad::sample_area(Vec2 u, InteractionDetail /*uv costs nothing here*/) const {
    // A parallelogram is the affine image of the unit square: uniform in (a, b) is uniform in area.
    return ShapeSample{corner_ + edge_u_ * u.x + edge_v_ * u.y, normal_, u, 1.0f / area_};
}

Bounds3 Quad::bounds() const {
    Bounds3 b;
    b.extend(corner_);
    b.extend(corner_ + edge_u_);
    b.extend(corner_ + edge_v_);
    b.extend(corner_ + edge_u_ + edge_v_);
    return b;
}

bool Quad::hit_parameters(const Vec3& origin, const Vec3& direction, float tmin, float tmax, float& t, float& a,
                          float& b) const {
    // Plane hit, then the coordinates (a, b) of the point in the (edge_u, edge_v) basis
    // from the dual basis: a = (w × edge_v)·n / (edge_u × edge_v)·n, likewise for b. A ray
    // parallel to the plane (denom 0) gets t = ±inf or NaN, which the range test refuses.
    const float denom = dot(normal_, direction);
    t = dot(normal_, corner_ - origin) / denom;
    const Vec3 w = origin + direction * t - corner_;
    a = dot(cross(w, edge_v_), cross_uv_) * inv_cross_uv2_;
    b = dot(cross(edge_u_, w), cross_uv_) * inv_cross_uv2_;
    return (denom != 0.0f) & (t > tmin) & (t < tmax) & (a >= 0.0f) & (a <= 1.0f) & (b >= 0.0f) & (b <= 1.0f);
}

Quad::PacketHitParameters Quad::hit_lanes(const RayPacket& packet) const {
    PacketHitParameters p;
    // Flags as wide as the floats: with bools GCC vectorised the loop two lanes at a time.
    uint32_t hit[RayPacket::kSize];
    for (uint32_t k = 0; k < RayPacket::kSize; ++k) {
        const Vec3 origin(packet.origin[0][k], packet.origin[1][k], packet.origin[2][k]);
        const Vec3 direction(packet.direction[0][k], packet.direction[1][k], packet.direction[2][k]);
        hit[k] = hit_parameters(origin, direction, packet.tmin[k], packet.tmax[k], p.t[k], p.a[k], p.b[k]);
    }
    for (uint32_t k = 0; k < RayPacket::kSize; ++k) p.lanes |= hit[k] << k;
    return p;
}

bool Quad::intersect(Ray& ray, Hit& hit) const {
    float t, a, b;
    if (!hit_parameters(ray.origin, ray.direction, ray.tmin, ray.tmax, t, a, b)) return false;
    ray.tmax = t;
    hit.t = t;
    hit.primitive = 0;
    hit.u = a;
    hit.v = b;
    return true;
}

bool Quad::occluded(const Ray& ray) const {
    float t, a, b;
    return hit_parameters(ray.origin, ray.direction, ray.tmin, ray.tmax, t, a, b);
}

uint32_t Quad::intersect_packet(RayPacket& packet, PacketHits& hits) const {
    const PacketHitParameters p = hit_lanes(packet);
    const uint32_t lanes = p.lanes & packet.active;
    for (uint32_t k = 0; k < RayPacket::kSize; ++k) {
        if (!(lanes >> k & 1)) continue;
        packet.tmax[k] = p.t[k];
        hits.set(k, Hit{.t = p.t[k], .primitive = 0, .u = p.a[k], .v = p.b[k]});
    }
    return lanes;
}

uint32_t Quad::occluded_packet(const RayPacket& packet) const { return hit_lanes(packet).lanes & packet.active; }

void Quad::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si, InteractionDetail) const {
    // Texture coordinates cost nothing here: set at every detail.
    si.p = corner_ + edge_u_ * hit.u + edge_v_ * hit.v;
    si.geometric_normal = normal_;
    si.shading_normal = normal_;
    si.uv = Vec2(hit.u, hit.v);
    si.dpdu = edge_u_;
    si.dpdv = edge_v_;
    si.front_face = dot(ray.direction, normal_) < 0.0f;
}

std::shared_ptr<Shape> Quad::from_params(const ParamTable& t, const BuildContext&) {
    const Vec3 corner = t.require_vec3("corner"), u = t.require_vec3("edge_u"), v = t.require_vec3("edge_v");
    if (!(length(cross(u, v)) > 0.0f))
        t.fail("edge_v", "an edge that is non-zero and not parallel to edge_u (a quad of positive area)");
    return std::make_shared<Quad>(corner, u, v);
}

std::shared_ptr<Shape> Quad::plane_from_params(const ParamTable& t, const BuildContext&) {
    const Vec3 center = t.vec3("center", Vec3(0.0f));
    const ParamValue& s = t.require("size", "the extent along x and z: a number or [sx, sz]");
    const Vec2 size = s.is_number() ? Vec2(s.as_float(t.name_of("size")), s.as_float(t.name_of("size")))
                                    : s.as_vec2(t.name_of("size"));
    if (!(size.x > 0.0f && size.y > 0.0f)) t.fail("size", "positive extents");
    // Facing +y, u along +x and v along -z, so textures read left to right seen from above.
    const Vec3 u(size.x, 0.0f, 0.0f), v(0.0f, 0.0f, -size.y);
    return std::make_shared<Quad>(center - u * 0.5f - v * 0.5f, u, v);
}

}  // namespace glint
