#include "glint/geometry/sphere.h"

#include "glint/math/constants.h"

#include <cmath>
#include <stdexcept>

namespace glint {

Sphere::Sphere(const Vec3& center, float radius) : center_(center), radius_(radius) {
    if (!(std::isfinite(radius) && radius > 0.0f)) throw std::invalid_argument("sphere radius must be finite and > 0");
    if (!is_finite(center)) throw std::invalid_argument("sphere center must be finite");
}

Bounds3 Sphere::bounds() const { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

bool Sphere::roots(const Ray& ray, float& t_near, float& t_far) const {
    // Numerically stable form (Haines et al., "Precision Improvements for Ray/Sphere
    // Intersection", Ray Tracing Gems ch. 7): the discriminant is computed from the
    // squared distance of the centre to the ray's line, not as the difference b² - ac of
    // two large numbers, and the roots as c/q and q/a to avoid cancellation.
    const Vec3 f = ray.origin - center_;
    const Vec3& d = ray.direction;
    const float a = dot(d, d);
    const float b = -dot(f, d);  // half of the usual -b
    const float c = dot(f, f) - radius_ * radius_;
    const Vec3 l = f + d * (b / a);
    const float discriminant = a * (radius_ * radius_ - dot(l, l));
    if (discriminant < 0.0f) return false;
    const float q = b + std::copysign(std::sqrt(discriminant), b);
    if (q == 0.0f) {
        t_near = t_far = 0.0f;
        return true;
    }
    t_near = c / q;
    t_far = q / a;
    if (t_near > t_far) std::swap(t_near, t_far);
    return true;
}

bool Sphere::intersect(Ray& ray, Hit& hit) const {
    float t0, t1;
    if (!roots(ray, t0, t1)) return false;
    float t = t0;
    if (!(t > ray.tmin && t < ray.tmax)) {
        t = t1;
        if (!(t > ray.tmin && t < ray.tmax)) return false;
    }
    ray.tmax = t;
    hit.t = t;
    hit.primitive = 0;
    hit.u = hit.v = 0.0f;
    return true;
}

bool Sphere::occluded(const Ray& ray) const {
    float t0, t1;
    if (!roots(ray, t0, t1)) return false;
    return (t0 > ray.tmin && t0 < ray.tmax) || (t1 > ray.tmin && t1 < ray.tmax);
}

void Sphere::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si) const {
    const Vec3 n = normalize(ray.at(hit.t) - center_);
    // Project the point onto the surface: removes the error of t along the ray.
    si.p = center_ + n * radius_;
    si.geometric_normal = n;
    si.shading_normal = n;
    float phi = std::atan2(n.z, n.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    si.uv = Vec2(phi / (2.0f * kPi), std::acos(std::clamp(n.y, -1.0f, 1.0f)) / kPi);
    si.front_face = dot(ray.direction, n) < 0.0f;
}

}  // namespace glint
