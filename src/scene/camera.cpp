#include "glint/scene/camera.h"

#include "glint/math/constants.h"
#include "glint/math/multiply_add.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glint {

Camera::Camera() : Camera(perspective({22.0f, 24.0f, 26.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 52.0f)) {}

Camera::Basis Camera::make_basis(const Vec3& eye, const Vec3& target, const Vec3& up) {
    const Vec3 view = target - eye;
    if (!(length(view) > 0.0f) || !is_finite(view)) throw std::invalid_argument("camera position equals its target");
    Basis b;
    b.eye = eye;
    b.forward = normalize(view);
    const Vec3 side = cross(b.forward, up);
    if (!(length(side) > 1e-6f * length(up)))
        throw std::invalid_argument("camera up vector is parallel to the view direction");
    b.right = normalize(side);                    // I_x = d_c × u_c
    b.up = normalize(cross(b.right, b.forward));  // u_c made orthogonal to d_c
    return b;
}

Camera::Camera(Projection projection, const Vec3& eye, const Vec3& target, const Vec3& up)
    : projection_(projection), target_(target), up_hint_(up) {
    const Basis b = make_basis(eye, target, up);
    eye_ = b.eye;
    forward_ = b.forward;
    right_ = b.right;
    up_ = b.up;
    // A lens given later focuses on the target unless told otherwise.
    lens_.focus_distance = length(target - eye);
}

void Camera::set_shutter(const Shutter& shutter) {
    if (!std::isfinite(shutter.open) || !std::isfinite(shutter.close))
        throw std::invalid_argument("shutter times must be finite");
    if (shutter.close < shutter.open) throw std::invalid_argument("the shutter closes before it opens");
    shutter_ = shutter;
}

void Camera::set_motion(std::vector<Key> keys) {
    if (keys.size() < 2) throw std::invalid_argument("a camera motion needs two keys or more");
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (!std::isfinite(keys[i].time)) throw std::invalid_argument("a camera key's time must be finite");
        if (i > 0 && !(keys[i].time > keys[i - 1].time))
            throw std::invalid_argument("camera keys must come in strictly increasing time");
    }
    // The view is a straight-line blend between keys; check it along the way (a pass of the
    // eye through the target, or a view along up, shows as a degenerate basis).
    constexpr int kChecks = 64;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i)
        for (int c = 0; c <= kChecks; ++c) {
            const float s = float(c) / float(kChecks);
            (void)make_basis(lerp(s, keys[i].eye, keys[i + 1].eye), lerp(s, keys[i].target, keys[i + 1].target),
                             up_hint_);
        }
    const Basis first = make_basis(keys.front().eye, keys.front().target, up_hint_);
    eye_ = first.eye;
    forward_ = first.forward;
    right_ = first.right;
    up_ = first.up;
    target_ = keys.front().target;
    keys_ = std::move(keys);
}

Camera::Basis Camera::basis_at(float time) const {
    if (keys_.empty() || !(time > keys_.front().time)) return {eye_, forward_, right_, up_};
    const Key& last = keys_.back();
    if (time >= last.time) return make_basis(last.eye, last.target, up_hint_);
    const auto next =
        std::upper_bound(keys_.begin(), keys_.end(), time, [](float t, const Key& key) { return t < key.time; });
    const Key& a = *(next - 1);
    const Key& b = *next;
    const float s = (time - a.time) / (b.time - a.time);
    return make_basis(lerp(s, a.eye, b.eye), lerp(s, a.target, b.target), up_hint_);
}

Camera Camera::perspective(const Vec3& eye, const Vec3& target, const Vec3& up, float vertical_fov) {
    if (!(vertical_fov > 0.0f && vertical_fov < 180.0f))
        throw std::invalid_argument("field of view must be between 0 and 180 degrees");
    Camera c(Projection::Perspective, eye, target, up);
    c.vertical_fov_ = vertical_fov;
    c.tan_half_fov_ = std::tan(radians(vertical_fov) * 0.5f);
    return c;
}

Camera Camera::orthographic(const Vec3& eye, const Vec3& target, const Vec3& up, float view_height) {
    if (!(view_height > 0.0f && std::isfinite(view_height)))
        throw std::invalid_argument("orthographic view height must be positive");
    Camera c(Projection::Orthographic, eye, target, up);
    c.view_height_ = view_height;
    return c;
}

void Camera::set_lens(const ThinLens& lens) {
    if (!(lens.aperture_radius >= 0.0f && std::isfinite(lens.aperture_radius)))
        throw std::invalid_argument("aperture radius must be zero or positive");
    if (!(lens.focus_distance > 0.0f && std::isfinite(lens.focus_distance)))
        throw std::invalid_argument("focus distance must be positive");
    if (!ThinLens::blades_allowed(lens.blades))
        throw std::invalid_argument(fmt::format("an aperture has 0 (round) or 3 to {} blades", ThinLens::kMaxBlades));
    if (!std::isfinite(lens.rotation)) throw std::invalid_argument("aperture rotation must be finite");
    lens_ = lens;
    aperture_ = Aperture(lens);
}

namespace {

/// Film position (x, y) in pixels as a screen position in [-1, 1]², (-1, -1) bottom-left
/// (handout §4.2.2).
[[gnu::always_inline]] inline Vec2 screen_position(float x, float y, int width, int height) {
    return {2.0f * x / float(width) - 1.0f, 1.0f - 2.0f * y / float(height)};
}

/// normalize(), its dot product rounded one fixed way (dot_fused).
[[gnu::always_inline]] inline Vec3 unit_vector(const Vec3& v) {
    const float length = std::sqrt(dot_fused(v, v));
    return {v.x / length, v.y / length, v.z / length};
}

}  // namespace

// Inlined into both generate_ray() and generate_rays(), so that one ray and eight get the
// same arithmetic, hence the same bits.
[[gnu::always_inline]] inline Vec3 Camera::image_plane_direction(const Basis& b, Vec2 screen, float aspect) const {
    // forward + (right·sx·aspect + up·sy)·tan(fov/2), each sum fused with its product.
    const float across = screen.x * aspect;
    auto axis = [&](int a) {
        return multiply_add(multiply_add(b.right[a], across, b.up[a] * screen.y), tan_half_fov_, b.forward[a]);
    };
    return {axis(0), axis(1), axis(2)};
}

Ray Camera::generate_ray(float x, float y, int width, int height, Vec2 u_lens, float time) const {
    // A camera that does not move (the common case) keeps its basis in registers: through
    // basis_at's call it came back in memory and was read at once, a store-forwarding stall
    // that cost every camera ray more than the rest of this function.
    const Basis b = keys_.empty() ? Basis{eye_, forward_, right_, up_} : basis_at(time);
    const Vec2 s = screen_position(x, y, width, height);
    const float aspect = float(width) / float(height);
    Vec3 origin = b.eye, direction = b.forward;
    if (projection_ == Projection::Orthographic) {
        const float half_h = 0.5f * view_height_;
        origin = b.eye + b.right * (s.x * half_h * aspect) + b.up * (s.y * half_h);
    } else {
        direction = image_plane_direction(b, s, aspect);
    }
    if (lens_.is_pinhole())
        return {origin, projection_ == Projection::Orthographic ? b.forward : unit_vector(direction), 0.0f, kInfinity,
                time};
    // The pinhole ray meets the plane of focus at origin + direction·focus_distance (its
    // direction has unit length along forward); the lens ray leaves from a point of the
    // aperture and passes there (pbrt-v4's PerspectiveCamera::GenerateRay).
    const Vec3 focus = origin + direction * lens_.focus_distance;
    const Vec2 a = aperture_.sample(u_lens);
    const Vec3 from = origin + b.right * a.x + b.up * a.y;
    return {from, normalize(focus - from), 0.0f, kInfinity, time};
}

void Camera::generate_rays(std::span<const Vec2> film, int width, int height, std::span<const Vec2> u_lens,
                           std::span<const float> times, std::span<Ray> rays) const {
    if (projection_ != Projection::Perspective || !lens_.is_pinhole() || moves()) {
        for (std::size_t k = 0; k < film.size(); ++k)
            rays[k] = generate_ray(film[k].x, film[k].y, width, height, u_lens[k], times[k]);
        return;
    }
    const Basis b{eye_, forward_, right_, up_};
    // Eight lanes in plain arrays (a short batch padded with the film's corner), one loop
    // over all eight that the compiler vectorises.
    constexpr std::size_t kBatch = 8;
    const float aspect = float(width) / float(height);
    for (std::size_t first = 0; first < film.size(); first += kBatch) {
        const std::size_t count = std::min(kBatch, film.size() - first);
        alignas(32) float x[kBatch] = {}, y[kBatch] = {}, dx[kBatch], dy[kBatch], dz[kBatch];
        for (std::size_t k = 0; k < count; ++k) {
            x[k] = film[first + k].x;
            y[k] = film[first + k].y;
        }
        for (std::size_t k = 0; k < kBatch; ++k) {
            const Vec3 d = unit_vector(image_plane_direction(b, screen_position(x[k], y[k], width, height), aspect));
            dx[k] = d.x;
            dy[k] = d.y;
            dz[k] = d.z;
        }
        for (std::size_t k = 0; k < count; ++k)
            rays[first + k] = Ray(b.eye, Vec3(dx[k], dy[k], dz[k]), 0.0f, kInfinity, times[first + k]);
    }
}

std::optional<Vec2> Camera::project(const Vec3& p, int width, int height) const {
    const float aspect = float(width) / float(height);
    const Vec3 d = p - eye_;
    float sx = 0.0f, sy = 0.0f;
    if (projection_ == Projection::Orthographic) {
        const float half_h = 0.5f * view_height_;
        sx = dot(d, right_) / (half_h * aspect);
        sy = dot(d, up_) / half_h;
    } else {
        const float depth = dot(d, forward_);
        if (!(depth > 0.0f)) return std::nullopt;
        sx = dot(d, right_) / (depth * tan_half_fov_ * aspect);
        sy = dot(d, up_) / (depth * tan_half_fov_);
    }
    return Vec2((sx + 1.0f) * 0.5f * float(width), (1.0f - sy) * 0.5f * float(height));
}

}  // namespace glint
