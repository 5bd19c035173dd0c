#pragma once
/// \file Axis-aligned box (rotate it with the object's transform).

#include "glint/geometry/shape.h"

namespace glint {

/// Solid box [lo, hi]. Hit.primitive is the face (0..5 = -x, +x, -y, +y, -z, +z);
/// uv spans each face from 0 to 1.
class Box final : public Shape {
public:
    /// Throws std::invalid_argument unless lo < hi on every axis.
    Box(const Vec3& lo, const Vec3& hi);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::shared_ptr<Shape> from_params(const ParamTable& params, const BuildContext& context);

    [[nodiscard]] Bounds3 bounds() const override { return box_; }
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] float area() const override;
    [[nodiscard]] std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] std::size_t memory_bytes() const override { return sizeof(*this); }
    [[nodiscard]] std::string_view type_name() const override { return "box"; }

private:
    bool entry_or_exit(const Ray& ray, float& t, int& face) const;

    Bounds3 box_;
};

}  // namespace glint
