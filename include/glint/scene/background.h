#pragma once
/// \file What rays that leave the scene see.

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <memory>
#include <optional>

namespace glint {

enum class BackgroundKind { Constant, SphereMap, Equirectangular, AngularMap };

/// Image coordinates in [0,1]² (v = 0 top row) of a world direction in a latitude-longitude
/// map: u = 0.5 + atan2(x, -z)/2π (the map's centre column looks along -z, +x is to its
/// right), v = acos(y)/π (+y at the top).
[[nodiscard]] Vec2 equirectangular_uv(const Vec3& direction);
/// Image coordinates of a world direction in a mirror-ball light probe photographed from
/// +z looking along -z (Debevec's "light probe" convention): the ball's normal is the
/// half-vector of the direction and +z, so the centre shows +z (behind the viewer) and
/// the rim shows -z; +y up, +x right.
[[nodiscard]] Vec2 sphere_map_uv(const Vec3& direction);
/// Image coordinates of a world direction in an angular map, Debevec's light-probe layout
/// ("Light Probe Image Gallery", https://www.pauldebevec.com/Probes/): "the center of the
/// image is straight forward, the circumference of the image is straight backwards, and the
/// horizontal line through the center linearly maps azimuthal angle to pixel coordinate".
/// Forward is -z, where the sphere map's camera looks: with (s, t) = (2u − 1, 1 − 2v) in the
/// unit disk, (s, t) = r·(x, y)/√(x² + y²) with r = acos(−z)/π, the angle from -z over π.
/// So the centre shows -z and the rim +z, the other way round from the sphere map (whose
/// centre reflects the camera). The page writes r = acos(D_z)/π in a frame whose forward is
/// +z; the shared venice_sunset angmap agrees with its lat-long map only as here. +x right,
/// +y up.
[[nodiscard]] Vec2 angular_map_uv(const Vec3& direction);

/// The inverses: the unit direction shown at image coordinates uv; nullopt outside the
/// disk of a sphere or angular map (the image's corners).
[[nodiscard]] Vec3 equirectangular_direction(Vec2 uv);
[[nodiscard]] std::optional<Vec3> sphere_map_direction(Vec2 uv);
[[nodiscard]] std::optional<Vec3> angular_map_direction(Vec2 uv);

class Background {
public:
    /// Black.
    Background() = default;
    [[nodiscard]] static Background constant(const Color& color);
    /// `rotation_degrees` turns the map about +y (counter-clockwise seen from above);
    /// `scale` multiplies its radiance.
    [[nodiscard]] static Background environment(BackgroundKind kind, std::shared_ptr<const Image> image,
                                                float rotation_degrees = 0.0f, float scale = 1.0f);

    /// Radiance arriving along -direction (i.e. seen looking along `direction`).
    [[nodiscard]] Color evaluate(const Vec3& direction) const;

    /// For a map: image coordinates of the world `direction` (rotation applied), and the
    /// unit world direction shown at `uv` (nullopt off a disk-shaped map's disk).
    [[nodiscard]] Vec2 uv_of(const Vec3& direction) const;
    [[nodiscard]] std::optional<Vec3> direction_of(Vec2 uv) const;

    [[nodiscard]] BackgroundKind kind() const { return kind_; }
    [[nodiscard]] const Color& color() const { return color_; }
    [[nodiscard]] const Image* image() const { return image_.get(); }
    /// What the map's radiance is multiplied by.
    [[nodiscard]] float scale() const { return scale_; }

private:
    BackgroundKind kind_ = BackgroundKind::Constant;
    Color color_{0.0f};
    std::shared_ptr<const Image> image_;
    float cos_rotation_ = 1.0f, sin_rotation_ = 0.0f;
    float scale_ = 1.0f;
};

}  // namespace glint
