#pragma once
/// \file The viewer's interactive camera: it orbits a target point about the world's up
/// axis, pans, dollies, flies, frames a box, and prints itself as a scene file's `[camera]`.
///
/// Angles: yaw about the up axis, pitch above the plane through the target normal to up,
/// kept within ±89° so that the view never flips. The up axis is the world axis (±x, ±y or
/// ±z) nearest the scene camera's up, so a z-up scan orbits about z.

#include "glint/math/bounds3.h"
#include "glint/math/vec3.h"
#include "glint/scene/camera.h"

#include <string>

namespace glint {

class OrbitCamera {
public:
    /// The orbit that shows what `camera` shows, pivoting about the point `focus_distance`
    /// ahead of it.
    [[nodiscard]] static OrbitCamera from(const Camera& camera, float focus_distance);

    [[nodiscard]] Camera camera() const;
    [[nodiscard]] Vec3 eye() const;
    [[nodiscard]] const Vec3& target() const { return target_; }
    [[nodiscard]] float distance() const { return distance_; }

    /// Turn about the target (radians); the pitch stops at ±89°.
    void orbit(float yaw, float pitch);
    /// Move eye and target together, across the view: by `right` and `up` times the distance.
    void pan(float right, float up);
    /// Scale the distance to the target (an orthographic view scales its height instead).
    void dolly(float factor);
    /// Move eye and target together along the view's right, up and forward axes.
    void fly(float right, float up, float forward);
    /// Look at the centre of `bounds` from the current direction, from where its bounding
    /// sphere just fills the view.
    void frame(const Bounds3& bounds);

    /// The `[camera]` table of a scene file that gives this view.
    [[nodiscard]] std::string toml() const;

private:
    Vec3 target_, up_;
    float yaw_ = 0.0f, pitch_ = 0.0f, distance_ = 1.0f;
    Projection projection_ = Projection::Perspective;
    float vertical_fov_ = 52.0f;  // degrees
    float view_height_ = 2.0f;
    /// The scene camera's lens, kept as it was (its plane of focus does not follow the orbit).
    ThinLens lens_;
    /// The scene camera's shutter, kept too (the orbit itself does not move over time).
    Shutter shutter_;
};

}  // namespace glint
