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
    area_ = length(n);
}

std::optional<ShapeSample> Quad::sample_area(Vec2 u) const {
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

bool Quad::hit_parameters(const Ray& ray, float& t, float& a, float& b) const {
    // Plane hit, then the coordinates (a, b) of the point in the (edge_u, edge_v) basis
    // from the dual basis: a = (w × edge_v)·n / (edge_u × edge_v)·n, likewise for b.
    const float denom = dot(normal_, ray.direction);
    if (denom == 0.0f) return false;
    t = dot(normal_, corner_ - ray.origin) / denom;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const Vec3 w = ray.at(t) - corner_;
    const Vec3 n = cross(edge_u_, edge_v_);
    const float inv = 1.0f / dot(n, n);
    a = dot(cross(w, edge_v_), n) * inv;
    b = dot(cross(edge_u_, w), n) * inv;
    return a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f;
}

bool Quad::intersect(Ray& ray, Hit& hit) const {
    float t, a, b;
    if (!hit_parameters(ray, t, a, b)) return false;
    ray.tmax = t;
    hit.t = t;
    hit.primitive = 0;
    hit.u = a;
    hit.v = b;
    return true;
}

bool Quad::occluded(const Ray& ray) const {
    float t, a, b;
    return hit_parameters(ray, t, a, b);
}

void Quad::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si) const {
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
