#pragma once
/// \file Perspective and orthographic cameras, pinhole or with a thin lens (depth of field).

#include "glint/math/ray.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"
#include "glint/scene/thin_lens.h"

#include <optional>
#include <span>
#include <vector>

namespace glint {

enum class Projection { Perspective, Orthographic };

/// When the shutter is open, in scene time (docs/scene-format.md): each camera ray takes a
/// time in [open, close], where moving objects and a moving camera are then. Open equal to
/// close is an instant: no blur.
struct Shutter {
    float open = 0.0f;
    float close = 1.0f;
    bool operator==(const Shutter&) const = default;
};

/// Built from look-at parameters, as the handout's image plane (§4.2): the view direction
/// d_c, the image plane's axes I_x = d_c × u_c and I_y = u_c (u_c made orthogonal to d_c),
/// half-height tan(θ/2) at distance 1 and half-width tan(θ/2)·aspect.
class Camera {
public:
    /// The default: the seminar's spheres camera.
    Camera();
    /// `vertical_fov` in degrees, in (0, 180).
    [[nodiscard]] static Camera perspective(const Vec3& eye, const Vec3& target, const Vec3& up, float vertical_fov);
    /// `view_height`: height of the visible region in world units.
    [[nodiscard]] static Camera orthographic(const Vec3& eye, const Vec3& target, const Vec3& up, float view_height);

    /// Give the camera a lens: depth of field (scene/thin_lens.h). Throws
    /// std::invalid_argument for a negative or non-finite aperture, a focus distance that is
    /// not positive, or 1, 2 or more than ThinLens::kMaxBlades blades.
    void set_lens(const ThinLens& lens);
    [[nodiscard]] const ThinLens& lens() const { return lens_; }

    /// Throws std::invalid_argument for a time that is not finite or close before open.
    void set_shutter(const Shutter& shutter);
    [[nodiscard]] const Shutter& shutter() const { return shutter_; }
    /// The time a camera ray takes for `u` in [0, 1): uniform over the shutter interval.
    [[nodiscard]] float time(float u) const { return shutter_.open + u * (shutter_.close - shutter_.open); }
    /// Where a moving camera is at one time: its eye and the point it looks at.
    struct Key {
        float time = 0.0f;
        Vec3 eye, target;
    };
    /// Move the camera through `keys` (two or more, at strictly increasing finite times): at
    /// a key's time it is at its eye looking at its target, in between on straight lines,
    /// and the first and last poses hold before and after. Its pose as made becomes the first
    /// key's. The keys objects use (transform and transform_end at times 0 and 1, or motion).
    /// Throws std::invalid_argument for fewer than two keys, times out of order, or a view
    /// that degenerates on the way (eye meeting target, view direction along up).
    void set_motion(std::vector<Key> keys);
    [[nodiscard]] bool moves() const { return !keys_.empty(); }
    /// The keys of a moving camera; empty for one that stays put.
    [[nodiscard]] const std::vector<Key>& motion() const { return keys_; }

    /// Ray through the film position (x, y) in pixels, (0, 0) = top-left corner of the
    /// image, (width, height) = bottom-right; the aspect ratio is width/height. Directions
    /// are unit length. With a lens, `u_lens` picks the point of the aperture the ray leaves
    /// from (Aperture::sample); a pinhole ignores it. The ray carries `time`, and a
    /// moving camera is where it is then.
    [[nodiscard]] Ray generate_ray(float x, float y, int width, int height, Vec2 u_lens = {}, float time = 0.0f) const;
    /// generate_ray() for each film position at once: rays[k] is the ray through film[k] with
    /// lens point u_lens[k] at times[k], bit for bit. A still perspective pinhole camera (the
    /// common case) makes them eight at a time with SIMD, so that the division, square root
    /// and division of a ray's direction overlap instead of following one another: the
    /// render's packets of camera rays (docs/performance.md). All four spans have one size.
    void generate_rays(std::span<const Vec2> film, int width, int height, std::span<const Vec2> u_lens,
                       std::span<const float> times, std::span<Ray> rays) const;
    /// Where world point `p` appears on a `width`×`height` film: the (x, y) that
    /// generate_ray() turns into a ray through `p` (for a lens: the ray from the aperture's
    /// centre; a moving camera's place at its first key); none for a point behind the eye. Used to
    /// draw rays over the image.
    [[nodiscard]] std::optional<Vec2> project(const Vec3& p, int width, int height) const;

    [[nodiscard]] Projection projection() const { return projection_; }
    [[nodiscard]] const Vec3& eye() const { return eye_; }
    [[nodiscard]] const Vec3& forward() const { return forward_; }
    [[nodiscard]] const Vec3& up() const { return up_; }
    [[nodiscard]] const Vec3& right() const { return right_; }
    [[nodiscard]] float vertical_fov() const { return vertical_fov_; }
    /// tan(vertical_fov / 2): half the image plane's height at distance 1 (perspective).
    [[nodiscard]] float tan_half_fov() const { return tan_half_fov_; }
    [[nodiscard]] float view_height() const { return view_height_; }

    /// Where the camera looks at time 0 and the up vector it was given.
    [[nodiscard]] const Vec3& target() const { return target_; }
    [[nodiscard]] const Vec3& up_hint() const { return up_hint_; }

private:
    /// The eye and the image plane's axes (handout §4.2).
    struct Basis {
        Vec3 eye, forward, right, up;
    };
    Camera(Projection projection, const Vec3& eye, const Vec3& target, const Vec3& up);
    /// Throws std::invalid_argument for a degenerate view.
    [[nodiscard]] static Basis make_basis(const Vec3& eye, const Vec3& target, const Vec3& up);
    [[nodiscard]] Basis basis_at(float time) const;
    /// The direction (not unit length) of a perspective camera's ray through a screen
    /// position in [-1, 1]²: the point of the image plane at distance 1.
    [[nodiscard]] Vec3 image_plane_direction(const Basis& b, Vec2 screen, float aspect) const;

    Projection projection_ = Projection::Perspective;
    Vec3 eye_, forward_, right_, up_;
    Vec3 target_, up_hint_;
    std::vector<Key> keys_;
    Shutter shutter_;
    float vertical_fov_ = 52.0f;  // degrees
    /// tan(vertical_fov_ / 2), set with it by perspective(): computed per camera ray it was
    /// 1 % of a render's time.
    float tan_half_fov_ = 0.0f;
    float view_height_ = 2.0f;
    ThinLens lens_;
    /// The lens's aperture, made with it by set_lens().
    Aperture aperture_;
};

}  // namespace glint
