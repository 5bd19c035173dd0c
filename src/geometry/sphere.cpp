#include "glint/geometry/sphere.h"

#include "glint/scene_format/param_table.h"

#include "glint/math/constants.h"
#include "glint/math/frame.h"
#include "glint/sampling/warp.h"

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

void Sphere::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si, InteractionDetail detail) const {
    const Vec3 n = normalize(ray.at(hit.t) - center_);
    // Project the point onto the surface: removes the error of t along the ray.
    si.p = center_ + n * radius_;
    si.geometric_normal = n;
    si.shading_normal = n;
    si.front_face = dot(ray.direction, n) < 0.0f;
    if (detail == InteractionDetail::WithoutTextureCoordinates) return;
    si.uv = uv_of(n);
    // p = c + r·(sinθ cosφ, cosθ, sinθ sinφ) with u = φ/2π, v = θ/π (uv_of).
    const float sin_theta = std::sqrt(n.x * n.x + n.z * n.z);
    si.dpdu = Vec3(-n.z, 0.0f, n.x) * (2.0f * kPi * radius_);
    si.dpdv = sin_theta > 1e-6f ? Vec3(n.y * n.x / sin_theta, -sin_theta, n.y * n.z / sin_theta) * (kPi * radius_)
                                : Vec3(kPi * radius_, 0.0f, 0.0f);
    si.curvature = 1.0f / radius_;
}

Vec2 Sphere::uv_of(const Vec3& n) {
    float phi = std::atan2(n.z, n.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    return Vec2(phi / (2.0f * kPi), std::acos(std::clamp(n.y, -1.0f, 1.0f)) / kPi);
}

float Sphere::area() const { return 4.0f * kPi * radius_ * radius_; }

std::optional<ShapeSample> Sphere::sample_area(Vec2 u, InteractionDetail detail) const {
    const Vec3 n = sample_uniform_sphere(u);
    return ShapeSample{center_ + n * radius_, n, detail == InteractionDetail::Full ? uv_of(n) : Vec2(), 1.0f / area()};
}

namespace {

/// sin²θmax of the cone a sphere of radius r subtends at distance d ≥ r from its centre.
float sin2_theta_max(float radius, float dist2) { return radius * radius / dist2; }

/// Below sin²(1.5°) the cone is too thin for 1 − cos θ in single precision: use the
/// Taylor expansion instead (pbrt-v4 §6.2.4).
constexpr float kThinCone = 0.00068523f;

}  // namespace

std::optional<ShapeSample> Sphere::sample_toward(const Vec3& ref, Vec2 u, InteractionDetail detail) const {
    const Vec3 to_center = center_ - ref;
    const float dist2 = dot(to_center, to_center);
    if (dist2 <= radius_ * radius_ * 1.0001f) return Shape::sample_toward(ref, u, detail);
    // Uniform direction in the cone, then the point where it meets the sphere, found from
    // the angle α at the centre (pbrt-v4 §6.2.4) rather than by a ray test that could miss
    // at the cone's rim.
    const float sin2_max = sin2_theta_max(radius_, dist2);
    const float sin_max = std::sqrt(sin2_max);
    float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2_max));
    float one_minus_cos_max = 1.0f - cos_max;
    float cos_theta = (cos_max - 1.0f) * u.x + 1.0f;
    float sin2_theta = 1.0f - cos_theta * cos_theta;
    if (sin2_max < kThinCone) {
        sin2_theta = sin2_max * u.x;
        cos_theta = std::sqrt(1.0f - sin2_theta);
        one_minus_cos_max = sin2_max / 2.0f;
    }
    const float cos_alpha =
        sin2_theta / sin_max + cos_theta * std::sqrt(std::max(0.0f, 1.0f - sin2_theta / (sin_max * sin_max)));
    const float sin_alpha = std::sqrt(std::max(0.0f, 1.0f - cos_alpha * cos_alpha));
    const float phi = 2.0f * kPi * u.y;
    Vec3 b1, b2;
    const Vec3 axis = normalize(to_center);
    orthonormal_basis(axis, b1, b2);
    // The surface normal points back towards the receiver, at angle α from −axis.
    const Vec3 n = -(b1 * (sin_alpha * std::cos(phi)) + b2 * (sin_alpha * std::sin(phi)) + axis * cos_alpha);
    return ShapeSample{center_ + n * radius_, n, detail == InteractionDetail::Full ? uv_of(n) : Vec2(),
                       1.0f / (2.0f * kPi * one_minus_cos_max)};
}

float Sphere::pdf_toward(const Vec3& ref, const Vec3& p, const Vec3& n) const {
    const Vec3 to_center = center_ - ref;
    const float dist2 = dot(to_center, to_center);
    if (dist2 <= radius_ * radius_ * 1.0001f) return Shape::pdf_toward(ref, p, n);
    const float sin2_max = sin2_theta_max(radius_, dist2);
    const float one_minus_cos_max =
        sin2_max < kThinCone ? sin2_max / 2.0f : 1.0f - std::sqrt(std::max(0.0f, 1.0f - sin2_max));
    return 1.0f / (2.0f * kPi * one_minus_cos_max);
}

std::shared_ptr<Shape> Sphere::from_params(const ParamTable& t, const BuildContext&) {
    const Vec3 center = t.vec3("center", Vec3(0.0f));
    const float radius = t.require_number("radius");
    if (!(radius > 0.0f)) t.fail("radius", "a positive radius");
    return std::make_shared<Sphere>(center, radius);
}

}  // namespace glint
