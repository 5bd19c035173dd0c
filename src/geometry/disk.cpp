#include "glint/geometry/disk.h"

#include "glint/scene_format/param_table.h"

#include "glint/math/constants.h"
#include "glint/math/frame.h"
#include "glint/sampling/warp.h"

#include <cmath>
#include <stdexcept>

namespace glint {

Disk::Disk(const Vec3& center, const Vec3& normal, float radius) : center_(center), radius_(radius) {
    if (!(std::isfinite(radius) && radius > 0.0f)) throw std::invalid_argument("disk radius must be finite and > 0");
    normal_ = normalize(normal);
    if (!is_finite(center) || !is_finite(normal_)) throw std::invalid_argument("disk needs a finite center and a non-zero normal");
    orthonormal_basis(normal_, tangent_, bitangent_);
}

Bounds3 Disk::bounds() const {
    // Per axis, the circle extends radius·sin(angle between the axis and the normal).
    Vec3 extent;
    for (int a = 0; a < 3; ++a) extent[a] = radius_ * std::sqrt(std::max(0.0f, 1.0f - normal_[a] * normal_[a]));
    return {center_ - extent, center_ + extent};
}

bool Disk::hit_parameters(const Ray& ray, float& t, float& x, float& y) const {
    const float denom = dot(normal_, ray.direction);
    if (denom == 0.0f) return false;
    t = dot(normal_, center_ - ray.origin) / denom;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const Vec3 w = ray.at(t) - center_;
    x = dot(w, tangent_);
    y = dot(w, bitangent_);
    return x * x + y * y <= radius_ * radius_;
}

bool Disk::intersect(Ray& ray, Hit& hit) const {
    float t, x, y;
    if (!hit_parameters(ray, t, x, y)) return false;
    ray.tmax = t;
    hit.t = t;
    hit.primitive = 0;
    hit.u = x;
    hit.v = y;
    return true;
}

bool Disk::occluded(const Ray& ray) const {
    float t, x, y;
    return hit_parameters(ray, t, x, y);
}

void Disk::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si, InteractionDetail detail) const {
    si.p = center_ + tangent_ * hit.u + bitangent_ * hit.v;
    si.geometric_normal = normal_;
    si.shading_normal = normal_;
    si.front_face = dot(ray.direction, normal_) < 0.0f;
    if (detail == InteractionDetail::WithoutTextureCoordinates) return;
    float phi = std::atan2(hit.v, hit.u);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const float rho = std::sqrt(hit.u * hit.u + hit.v * hit.v);
    si.uv = Vec2(rho / radius_, phi / (2.0f * kPi));
    // u = ρ/R along the radius, v = φ/2π around it.
    const Vec3 radial = tangent_ * std::cos(phi) + bitangent_ * std::sin(phi);
    si.dpdu = radial * radius_;
    si.dpdv = cross(normal_, radial) * (2.0f * kPi * rho);
}

float Disk::area() const { return kPi * radius_ * radius_; }

std::optional<ShapeSample> Disk::sample_area(Vec2 u, InteractionDetail detail) const {
    const Vec2 d = sample_uniform_disk_concentric(u) * radius_;
    ShapeSample s{center_ + tangent_ * d.x + bitangent_ * d.y, normal_, Vec2(), 1.0f / area()};
    if (detail == InteractionDetail::Full) {
        float phi = std::atan2(d.y, d.x);
        if (phi < 0.0f) phi += 2.0f * kPi;
        s.uv = Vec2(std::sqrt(d.x * d.x + d.y * d.y) / radius_, phi / (2.0f * kPi));
    }
    return s;
}

std::shared_ptr<Shape> Disk::from_params_facing(const ParamTable& t, const Vec3& default_normal) {
    const Vec3 normal = t.vec3("normal", default_normal);
    if (!(length(normal) > 0.0f)) t.fail("normal", "a non-zero direction the disk faces");
    const float radius = t.require_number("radius");
    if (!(radius > 0.0f)) t.fail("radius", "a positive radius");
    return std::make_shared<Disk>(t.vec3("center", Vec3(0.0f)), normal, radius);
}

std::shared_ptr<Shape> Disk::from_params(const ParamTable& t, const BuildContext&) {
    return from_params_facing(t, Vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace glint
