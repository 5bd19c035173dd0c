#pragma once
/// \file What rays that leave the scene see.

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <memory>

namespace glint {

enum class BackgroundKind { Constant, SphereMap, Equirectangular };

/// Image coordinates in [0,1]² (v = 0 top row) of a world direction in a latitude-longitude
/// map: u = 0.5 + atan2(x, -z)/2π (the map's centre column looks along -z, +x is to its
/// right), v = acos(y)/π (+y at the top).
[[nodiscard]] Vec2 equirectangular_uv(const Vec3& direction);
/// Image coordinates of a world direction in a mirror-ball light probe photographed from
/// +z looking along -z (Debevec's "light probe" convention): the ball's normal is the
/// half-vector of the direction and +z, so the centre shows +z (behind the viewer) and
/// the rim shows -z; +y up, +x right.
[[nodiscard]] Vec2 sphere_map_uv(const Vec3& direction);

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

    [[nodiscard]] BackgroundKind kind() const { return kind_; }
    [[nodiscard]] const Color& color() const { return color_; }
    [[nodiscard]] const Image* image() const { return image_.get(); }

private:
    BackgroundKind kind_ = BackgroundKind::Constant;
    Color color_{0.0f};
    std::shared_ptr<const Image> image_;
    float cos_rotation_ = 1.0f, sin_rotation_ = 0.0f;
    float scale_ = 1.0f;
};

}  // namespace glint
