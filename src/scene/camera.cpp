#include "glint/scene/camera.h"

#include "glint/math/constants.h"

#include <cmath>
#include <stdexcept>

namespace glint {

Camera::Camera() : Camera(perspective({22.0f, 24.0f, 26.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 52.0f)) {}

Camera::Camera(Projection projection, const Vec3& eye, const Vec3& target, const Vec3& up)
    : projection_(projection), eye_(eye) {
    const Vec3 view = target - eye;
    if (!(length(view) > 0.0f) || !is_finite(view)) throw std::invalid_argument("camera position equals its target");
    forward_ = normalize(view);
    const Vec3 side = cross(forward_, up);
    if (!(length(side) > 1e-6f * length(up)))
        throw std::invalid_argument("camera up vector is parallel to the view direction");
    right_ = normalize(side);                  // I_x = d_c × u_c
    up_ = normalize(cross(right_, forward_));  // u_c made orthogonal to d_c
    // A lens given later focuses on the target unless told otherwise.
    lens_.focus_distance = length(view);
}

Camera Camera::perspective(const Vec3& eye, const Vec3& target, const Vec3& up, float vertical_fov) {
    if (!(vertical_fov > 0.0f && vertical_fov < 180.0f))
        throw std::invalid_argument("field of view must be between 0 and 180 degrees");
    Camera c(Projection::Perspective, eye, target, up);
    c.vertical_fov_ = vertical_fov;
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
    if (lens.blades == 1 || lens.blades == 2) throw std::invalid_argument("an aperture has 0 (round) or 3+ blades");
    if (!std::isfinite(lens.rotation)) throw std::invalid_argument("aperture rotation must be finite");
    lens_ = lens;
}

Ray Camera::generate_ray(float x, float y, int width, int height, Vec2 u_lens) const {
    // Screen position in [-1, 1]², (-1, -1) bottom-left (handout §4.2.2).
    const float sx = 2.0f * x / float(width) - 1.0f;
    const float sy = 1.0f - 2.0f * y / float(height);
    const float aspect = float(width) / float(height);
    Vec3 origin = eye_, direction = forward_;
    if (projection_ == Projection::Orthographic) {
        const float half_h = 0.5f * view_height_;
        origin = eye_ + right_ * (sx * half_h * aspect) + up_ * (sy * half_h);
    } else {
        const float tan_half = std::tan(radians(vertical_fov_) * 0.5f);
        direction = forward_ + (right_ * (sx * aspect) + up_ * sy) * tan_half;
    }
    if (lens_.is_pinhole()) return {origin, projection_ == Projection::Orthographic ? forward_ : normalize(direction)};
    // The pinhole ray meets the plane of focus at origin + direction·focus_distance (its
    // direction has unit length along forward); the lens ray leaves from a point of the
    // aperture and passes there (pbrt-v4's PerspectiveCamera::GenerateRay).
    const Vec3 focus = origin + direction * lens_.focus_distance;
    const Vec2 a = lens_.sample_aperture(u_lens);
    const Vec3 from = origin + right_ * a.x + up_ * a.y;
    return {from, normalize(focus - from)};
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
        const float tan_half = std::tan(radians(vertical_fov_) * 0.5f);
        sx = dot(d, right_) / (depth * tan_half * aspect);
        sy = dot(d, up_) / (depth * tan_half);
    }
    return Vec2((sx + 1.0f) * 0.5f * float(width), (1.0f - sy) * 0.5f * float(height));
}

}  // namespace glint
