#include "glint/geometry/sphere.h"

#include "glint/scene_format/param_table.h"

#include "glint/math/constants.h"
#include "glint/math/frame.h"
#include "glint/math/multiply_add.h"
#include "glint/sampling/warp.h"

#include <cmath>
#include <stdexcept>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace glint {

Sphere::Sphere(const Vec3& center, float radius) : center_(center), radius_(radius) {
    if (!(std::isfinite(radius) && radius > 0.0f)) throw std::invalid_argument("sphere radius must be finite and > 0");
    if (!is_finite(center)) throw std::invalid_argument("sphere center must be finite");
}

Bounds3 Sphere::bounds() const { return {center_ - Vec3(radius_), center_ + Vec3(radius_)}; }

// Inlined into intersect() and occluded(): called, it handed its roots back through memory.
[[gnu::always_inline]] inline bool Sphere::roots(const Ray& ray, float& t_near, float& t_far) const {
    // Numerically stable form (Haines et al., "Precision Improvements for Ray/Sphere
    // Intersection", Ray Tracing Gems ch. 7): the discriminant is computed from the
    // squared distance of the centre to the ray's line, not as the difference b² - ac of
    // two large numbers, and the roots as c/q and q/a to avoid cancellation. Each product
    // is rounded as occluded_packet() rounds it (multiply_add), so that a shadow ray gets
    // the same answer alone and in a packet.
    const Vec3 f = ray.origin - center_;
    const Vec3& d = ray.direction;
    const float a = dot_fused(d, d);
    const float b = -dot_fused(f, d);  // half of the usual -b
    const float c = multiply_add(-radius_, radius_, dot_fused(f, f));
    const float b_over_a = b / a;
    const Vec3 l(multiply_add(d.x, b_over_a, f.x), multiply_add(d.y, b_over_a, f.y), multiply_add(d.z, b_over_a, f.z));
    const float discriminant = a * multiply_add(radius_, radius_, -dot_fused(l, l));
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

uint32_t Sphere::occluded_packet(const RayPacket& packet) const {
#if defined(__AVX2__) && defined(__FMA__)
    // roots() and occluded() for eight lanes at once, without branches, rounded as they are.
    // Where q = 0 the near root comes out ±inf or NaN instead of 0 and the far one 0, which
    // (tmin, tmax) holds or not as 0 would.
    const auto load = [](const float* lanes) { return _mm256_load_ps(lanes); };
    const auto dot = [](__m256 ax, __m256 ay, __m256 az, __m256 bx, __m256 by, __m256 bz) {
        return _mm256_fmadd_ps(az, bz, _mm256_fmadd_ps(ay, by, _mm256_mul_ps(ax, bx)));
    };
    const __m256 fx = _mm256_sub_ps(load(packet.origin[0]), _mm256_set1_ps(center_.x));
    const __m256 fy = _mm256_sub_ps(load(packet.origin[1]), _mm256_set1_ps(center_.y));
    const __m256 fz = _mm256_sub_ps(load(packet.origin[2]), _mm256_set1_ps(center_.z));
    const __m256 dx = load(packet.direction[0]), dy = load(packet.direction[1]), dz = load(packet.direction[2]);
    const __m256 radius = _mm256_set1_ps(radius_), sign_bit = _mm256_set1_ps(-0.0f), zero = _mm256_setzero_ps();
    const __m256 a = dot(dx, dy, dz, dx, dy, dz);
    const __m256 b = _mm256_xor_ps(dot(fx, fy, fz, dx, dy, dz), sign_bit);
    const __m256 c = _mm256_fnmadd_ps(radius, radius, dot(fx, fy, fz, fx, fy, fz));
    const __m256 b_over_a = _mm256_div_ps(b, a);
    const __m256 lx = _mm256_fmadd_ps(dx, b_over_a, fx), ly = _mm256_fmadd_ps(dy, b_over_a, fy),
                 lz = _mm256_fmadd_ps(dz, b_over_a, fz);
    const __m256 discriminant = _mm256_mul_ps(a, _mm256_fmsub_ps(radius, radius, dot(lx, ly, lz, lx, ly, lz)));
    const __m256 root = _mm256_sqrt_ps(_mm256_max_ps(discriminant, zero));
    const __m256 q = _mm256_add_ps(b, _mm256_or_ps(root, _mm256_and_ps(b, sign_bit)));  // b + copysign(root, b)
    const __m256 t0 = _mm256_div_ps(c, q), t1 = _mm256_div_ps(q, a);
    const __m256 tmin = load(packet.tmin), tmax = load(packet.tmax);
    const auto within = [&](__m256 t) {
        return _mm256_and_ps(_mm256_cmp_ps(t, tmin, _CMP_GT_OQ), _mm256_cmp_ps(t, tmax, _CMP_LT_OQ));
    };
    const __m256 hit =
        _mm256_and_ps(_mm256_cmp_ps(discriminant, zero, _CMP_GE_OQ), _mm256_or_ps(within(t0), within(t1)));
    return static_cast<uint32_t>(_mm256_movemask_ps(hit)) & packet.active;
#else
    return Shape::occluded_packet(packet);
#endif
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
