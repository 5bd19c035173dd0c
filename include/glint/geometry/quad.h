#pragma once
/// \file Parallelogram (a finite plane).

#include "glint/geometry/shape.h"

namespace glint {

/// The parallelogram corner + a·edge_u + b·edge_v, a, b in [0, 1]; uv = (a, b);
/// the normal is normalize(edge_u × edge_v).
class Quad final : public Shape {
public:
    /// Throws std::invalid_argument if the edges are parallel or zero.
    Quad(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::shared_ptr<Shape> from_params(const ParamTable& params, const BuildContext& context);
    /// `type = "plane"`: a quad centred on `center`, facing +y, of `size` along x and z.
    [[nodiscard]] static std::shared_ptr<Shape> plane_from_params(const ParamTable& params, const BuildContext& context);

    [[nodiscard]] Bounds3 bounds() const override;
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si) const override;
    [[nodiscard]] float area() const override { return area_; }
    [[nodiscard]] std::optional<ShapeSample> sample_area(Vec2 u) const override;
    [[nodiscard]] std::size_t memory_bytes() const override { return sizeof(*this); }
    [[nodiscard]] std::string_view type_name() const override { return "quad"; }

private:
    bool hit_parameters(const Ray& ray, float& t, float& a, float& b) const;

    Vec3 corner_, edge_u_, edge_v_, normal_;
    float area_ = 0.0f;
};

}  // namespace glint
