#pragma once
/// \file A diffuse area light bound to a shape (pbrt-v4's DiffuseAreaLight).

#include "glint/geometry/shape.h"
#include "glint/lights/light.h"
#include "glint/materials/texture.h"
#include "glint/math/transform.h"

#include <memory>
#include <optional>

namespace glint {

/// A shape placed in the world that emits radiance `radiance` (× `texture` at the point's
/// uv, if given) uniformly in angle. One-sided lights emit on the side of the shape's
/// outward normal (a quad's edge_u × edge_v); two-sided ones on both.
///
/// Sampling, from a receiving point:
/// - shapes with solid-angle sampling (spheres seen from outside) use it whenever the
///   placement is a similarity (rotation, translation, uniform scale), which preserves
///   solid angles;
/// - otherwise a point uniform over the object-space area, whose world-space density is
///   divided by the area scale |det A|·|A^{-T} n| of the transform at that point, then
///   converted to solid angle by d²/|cos θ_light|.
class AreaLight final : public Light {
public:
    /// Throws std::invalid_argument if the shape has no area to sample.
    AreaLight(std::shared_ptr<Shape> shape, const std::optional<Transform>& world_from_object, const Color& radiance,
              const Texture* texture, bool two_sided);

    /// The scene-file factories of `[[lights]]` type sphere, quad and disk
    /// (docs/scene-format.md): each reads the shape's keys and `radiance`, `transform`,
    /// `name` (and `two_sided` where a shape has two sides) and adds the light, with the
    /// object it is, to the context's scene. A disk faces down unless told otherwise.
    static void add_sphere_from_params(const ParamTable& params, BuildContext& context);
    static void add_quad_from_params(const ParamTable& params, BuildContext& context);
    static void add_disk_from_params(const ParamTable& params, BuildContext& context);

    [[nodiscard]] LightSample sample(const Vec3& point, Vec2 u) const override;
    [[nodiscard]] float pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const override;
    [[nodiscard]] std::string_view type_name() const override { return "area"; }

    /// Radiance leaving the surface point p with unit outward normal `n` (world) and texture
    /// coordinates `uv` in the unit direction `w` (pointing away from the surface).
    [[nodiscard]] Color emitted(const Vec3& p, const Vec3& n, Vec2 uv, const Vec3& w) const;
    [[nodiscard]] const Color& radiance() const { return radiance_; }
    [[nodiscard]] bool two_sided() const { return two_sided_; }
    [[nodiscard]] const Shape& shape() const { return *shape_; }

private:
    /// World-space density per unit area at a point with world normal n, for area sampling.
    [[nodiscard]] float area_pdf(const Vec3& world_normal) const;

    std::shared_ptr<Shape> shape_;
    std::optional<Transform> world_from_object_;
    std::optional<Transform> object_from_world_;
    bool similarity_ = true;
    float det_ = 1.0f;
    Color radiance_;
    const Texture* texture_;
    bool two_sided_;
};

}  // namespace glint
