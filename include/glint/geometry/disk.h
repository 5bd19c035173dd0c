#pragma once
/// \file Disk: a flat circle, the usual shape of a lamp's opening.

#include "glint/geometry/shape.h"

namespace glint {

/// The points within `radius` of `center` in the plane through it perpendicular to
/// `normal`. uv = (r/radius, φ/2π), φ measured from the first tangent of the normal's
/// orthonormal basis (Duff et al. 2017).
class Disk final : public Shape {
public:
    /// Throws std::invalid_argument for a radius that is not finite and positive, or a zero normal.
    Disk(const Vec3& center, const Vec3& normal, float radius);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    /// The disk faces `default_normal` unless the table gives a `normal`.
    [[nodiscard]] static std::shared_ptr<Shape> from_params_facing(const ParamTable& params, const Vec3& default_normal);
    /// The `[[objects]]` disk, facing +y by default.
    [[nodiscard]] static std::shared_ptr<Shape> from_params(const ParamTable& params, const BuildContext& context);

    [[nodiscard]] Bounds3 bounds() const override;
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] float area() const override;
    /// Shirley & Chiu's concentric map: uniform in area, strata kept compact.
    [[nodiscard]] std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] std::size_t memory_bytes() const override { return sizeof(*this); }
    [[nodiscard]] std::string_view type_name() const override { return "disk"; }

private:
    /// Plane hit with t in the ray's range and within the radius; the hit's local (x, y).
    bool hit_parameters(const Ray& ray, float& t, float& x, float& y) const;

    Vec3 center_, normal_, tangent_, bitangent_;
    float radius_;
};

}  // namespace glint
