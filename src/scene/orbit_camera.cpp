#include "glint/scene/orbit_camera.h"

#include "glint/math/constants.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

constexpr float kMaxPitch = 89.0f * kPi / 180.0f;

/// The world axis, with its sign, nearest `v`.
Vec3 nearest_axis(const Vec3& v) {
    const float ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
    if (ay >= ax && ay >= az) return {0.0f, v.y < 0.0f ? -1.0f : 1.0f, 0.0f};
    if (az >= ax) return {0.0f, 0.0f, v.z < 0.0f ? -1.0f : 1.0f};
    return {v.x < 0.0f ? -1.0f : 1.0f, 0.0f, 0.0f};
}

/// Two unit axes that make a right-handed frame with the axis `up`.
void horizontal_axes(const Vec3& up, Vec3& a, Vec3& b) {
    a = std::abs(up.y) > 0.5f ? Vec3(0.0f, 0.0f, 1.0f) : Vec3(0.0f, 1.0f, 0.0f);
    a = normalize(a - up * dot(a, up));
    b = cross(up, a);
}

}  // namespace

OrbitCamera OrbitCamera::from(const Camera& camera, float focus_distance) {
    OrbitCamera orbit;
    orbit.up_ = nearest_axis(camera.up());
    orbit.distance_ = std::max(focus_distance, 1e-4f);
    orbit.target_ = camera.eye() + camera.forward() * orbit.distance_;
    orbit.projection_ = camera.projection();
    orbit.vertical_fov_ = camera.vertical_fov();
    orbit.view_height_ = camera.view_height();
    orbit.lens_ = camera.lens();
    orbit.shutter_ = camera.shutter();
    Vec3 a, b;
    horizontal_axes(orbit.up_, a, b);
    const Vec3 to_eye = -camera.forward();
    orbit.pitch_ = std::clamp(std::asin(std::clamp(dot(to_eye, orbit.up_), -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    orbit.yaw_ = std::atan2(dot(to_eye, b), dot(to_eye, a));
    return orbit;
}

Vec3 OrbitCamera::eye() const {
    Vec3 a, b;
    horizontal_axes(up_, a, b);
    const Vec3 to_eye = (a * std::cos(yaw_) + b * std::sin(yaw_)) * std::cos(pitch_) + up_ * std::sin(pitch_);
    return target_ + to_eye * distance_;
}

Camera OrbitCamera::camera() const {
    Camera view = projection_ == Projection::Orthographic ? Camera::orthographic(eye(), target_, up_, view_height_)
                                                          : Camera::perspective(eye(), target_, up_, vertical_fov_);
    view.set_lens(lens_);
    view.set_shutter(shutter_);
    return view;
}

void OrbitCamera::orbit(float yaw, float pitch) {
    yaw_ = std::remainder(yaw_ + yaw, 2.0f * kPi);
    pitch_ = std::clamp(pitch_ + pitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float right, float up) {
    const Camera view = camera();
    target_ += (view.right() * right + view.up() * up) * distance_;
}

void OrbitCamera::dolly(float factor) {
    if (!(factor > 0.0f)) return;
    if (projection_ == Projection::Orthographic)
        view_height_ = std::max(view_height_ * factor, 1e-6f);
    else
        distance_ = std::max(distance_ * factor, 1e-4f);
}

void OrbitCamera::fly(float right, float up, float forward) {
    const Camera view = camera();
    target_ += view.right() * right + view.up() * up + view.forward() * forward;
}

void OrbitCamera::frame(const Bounds3& bounds) {
    if (bounds.empty()) return;
    target_ = bounds.center();
    const float radius = std::max(0.5f * length(bounds.diagonal()), 1e-4f);
    if (projection_ == Projection::Orthographic) {
        view_height_ = 2.0f * radius;
        distance_ = 2.0f * radius;
    } else {
        // The sphere fills the vertical field of view: sin(fov/2) = radius / distance.
        distance_ = radius / std::sin(0.5f * vertical_fov_ * kPi / 180.0f);
    }
}

std::string OrbitCamera::toml() const {
    const Vec3 e = eye();
    std::string text = "[camera]\n";
    if (projection_ == Projection::Orthographic) text += "type = \"orthographic\"\n";
    // Seven significant digits: what a float holds, without the noise of its last bit
    // (21.999998 for the 22 a scene file said).
    text += fmt::format("position = [{:.7g}, {:.7g}, {:.7g}]\nlook_at = [{:.7g}, {:.7g}, {:.7g}]\nup = [{}, {}, {}]\n",
                        e.x, e.y, e.z, target_.x, target_.y, target_.z, up_.x, up_.y, up_.z);
    text += projection_ == Projection::Orthographic ? fmt::format("height = {:.7g}\n", view_height_)
                                                    : fmt::format("fov = {:.7g}\n", vertical_fov_);
    if (!lens_.is_pinhole()) {
        text += fmt::format("aperture_radius = {:.7g}\nfocus_distance = {:.7g}\n", lens_.aperture_radius,
                            lens_.focus_distance);
        if (lens_.blades != 0)
            text += fmt::format("aperture_blades = {}\naperture_rotation = {:.7g}\n", lens_.blades, lens_.rotation);
    }
    if (shutter_ != Shutter{}) text += fmt::format("shutter = [{:.7g}, {:.7g}]\n", shutter_.open, shutter_.close);
    return text;
}

}  // namespace glint
