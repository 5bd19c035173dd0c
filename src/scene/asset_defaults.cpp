#include "glint/scene/asset_defaults.h"

#include "glint/diagnostics.h"
#include "glint/math/constants.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint {

namespace {

/// Where the automatic camera stands, relative to the centre (scaled to the distance).
constexpr double kFromFrontYUp[3] = {0.0, 0.35, 1.0};
constexpr double kFromFrontZUp[3] = {0.0, -1.0, 0.35};
constexpr double kFromFrontXUp[3] = {0.35, 0.0, 1.0};

}  // namespace

std::optional<UpAxis> parse_up_axis(std::string_view name) {
    if (name == "x") return UpAxis::X;
    if (name == "y") return UpAxis::Y;
    if (name == "z") return UpAxis::Z;
    return std::nullopt;
}

Camera framing_camera(const Bounds3& bounds, float aspect, const std::filesystem::path& file, UpAxis up) {
    // In double precision: a float diagonal of finite but huge bounds overflows.
    double center[3] = {0.0, 0.0, 0.0}, diagonal_squared = 0.0, center_extent = 0.0;
    if (!bounds.empty())
        for (int axis = 0; axis < 3; ++axis) {
            center[axis] = 0.5 * (double(bounds.lo[axis]) + double(bounds.hi[axis]));
            const double side = double(bounds.hi[axis]) - double(bounds.lo[axis]);
            diagonal_squared += side * side;
            center_extent = std::max(center_extent, std::abs(center[axis]));
        }
    // At least a few float steps of the centre's coordinates away, so the eye differs from
    // the target after rounding to float even for a tiny object far from the origin.
    const double radius = bounds.empty() ? 1.0 : std::max({0.5 * std::sqrt(diagonal_squared), 1e-6, 4e-7 * center_extent});
    constexpr float vertical_fov = 40.0f;
    // The sphere must fit the narrower of the two fields of view.
    const double half_vertical = double(vertical_fov) * std::numbers::pi / 180.0 * 0.5;
    const double half_horizontal = std::atan(std::tan(half_vertical) * double(aspect));
    const double distance = 1.05 * radius / std::sin(std::min(half_vertical, half_horizontal));
    // From the front, raised by 0.35 along the up axis.
    const double(&offset)[3] = up == UpAxis::Y   ? kFromFrontYUp
                               : up == UpAxis::Z ? kFromFrontZUp
                                                 : kFromFrontXUp;
    const double offset_length = std::sqrt(0.35 * 0.35 + 1.0);
    Vec3 eye, target;
    for (int axis = 0; axis < 3; ++axis) {
        const double e = center[axis] + offset[axis] / offset_length * distance;
        // Squared lengths of camera vectors must stay finite in float.
        if (!(std::abs(e) <= kMaxFramedCoordinate))
            throw SceneError(fmt::format("{}: the geometry spans ({}, {}, {}) to ({}, {}, {}): too large or too far away for "
                                         "an automatic camera, which would stand beyond ±{:g} (give the scene a camera)",
                                         file.string(), bounds.lo.x, bounds.lo.y, bounds.lo.z, bounds.hi.x, bounds.hi.y,
                                         bounds.hi.z, kMaxFramedCoordinate));
        eye[axis] = float(e);
        target[axis] = float(center[axis]);
    }
    const Vec3 up_vector = up == UpAxis::Y ? Vec3(0, 1, 0) : up == UpAxis::Z ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
    return Camera::perspective(eye, target, up_vector, vertical_fov);
}

void add_default_lighting(Scene& scene) {
    const Camera& c = scene.camera;
    // Travelling forward, down and to the right: the light comes from the camera's upper left.
    const Vec3 travel = normalize(c.forward() + c.right() * 0.5f - c.up() * 0.7f);
    scene.add_light(std::make_unique<DirectionalLight>(travel, Color(kDefaultKeyLight)));
    scene.background = Background::constant(Color(kDefaultSky));
    scene.ambient_light = Color(kDefaultSky);
}

}  // namespace glint
