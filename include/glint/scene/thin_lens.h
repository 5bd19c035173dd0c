#pragma once
/// \file The thin lens: depth of field for a camera (Potmesil & Chakravarty 1981; Cook,
/// Porter & Carpenter 1984; pbrt-v4 §5.2.3).
///
/// A ray leaves a point of the aperture (a disk, or a regular polygon for a diaphragm with
/// blades) and passes through the point of the plane of focus that the pinhole ray through
/// the same film position meets. Points on that plane (normal to the view direction, at
/// `focus_distance` from the eye) are sharp; a point at depth z along the view direction
/// spreads over a disk (or polygon) of radius
///
///     r(z) = aperture_radius · |1 − focus_distance / z|
///
/// measured in the plane of focus; on the image that is r(z) / (focus_distance · tan(fov/2))
/// half-heights. That is the thin-lens circle of confusion c = A·f·|z − z_f| / (z·(z_f − f))
/// (A the aperture diameter, f the focal length) scaled from the sensor to the plane of focus.

#include "glint/math/constants.h"
#include "glint/math/vec2.h"
#include "glint/sampling/warp.h"

#include <cmath>
#include <cstdint>
#include <optional>

namespace glint {

struct ThinLens {
    /// Radius of the aperture in world units; 0 is a pinhole (everything sharp).
    float aperture_radius = 0.0f;
    /// Distance from the eye to the plane of focus, along the view direction, world units.
    /// A camera's starts at the distance to its look-at point.
    float focus_distance = 1.0f;
    /// Number of diaphragm blades: 0 for a round aperture, else 3 to kMaxBlades (a regular
    /// polygon whose corners lie on the aperture's circle).
    uint32_t blades = 0;
    /// Beyond this many blades the polygon is a circle to the eye; the aperture keeps a
    /// table of its corners.
    static constexpr uint32_t kMaxBlades = 64;
    /// Whether a lens may have `n` blades: 0 (round), or 3 to kMaxBlades.
    [[nodiscard]] static constexpr bool blades_allowed(uint32_t n) { return n == 0 || (n >= 3 && n <= kMaxBlades); }
    /// Turn of the polygon in degrees (its first corner at this angle from the camera's
    /// right axis, counter-clockwise as seen from behind the camera).
    float rotation = 0.0f;

    [[nodiscard]] bool is_pinhole() const { return !(aperture_radius > 0.0f); }
};

/// The points a thin lens's rays leave from, uniform over its aperture's area, in world
/// units, (right, up) in the lens plane: stratified `u` give stratified points (concentric
/// disk map; polygon wedges). Made from a ThinLens, whose blades it turns into their
/// corners once.
class Aperture {
public:
    /// A pinhole's: every point is the centre.
    Aperture() = default;
    explicit Aperture(const ThinLens& lens)
        : radius_(lens.aperture_radius),
          polygon_(lens.blades == 0 ? std::nullopt
                                    : std::optional(UniformRegularPolygon(lens.blades, radians(lens.rotation)))) {}

    [[nodiscard]] Vec2 sample(Vec2 u) const {
        const Vec2 p = polygon_ ? polygon_->sample(u) : sample_uniform_disk_concentric(u);
        return p * radius_;
    }

private:
    float radius_ = 0.0f;
    /// The blades' polygon; none for a round aperture.
    std::optional<UniformRegularPolygon> polygon_;
};

}  // namespace glint
