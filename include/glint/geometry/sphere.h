#pragma once
/// \file Sphere.

#include "glint/geometry/shape.h"

namespace glint {

/// A sphere of a given centre and radius. uv: u = azimuth φ/2π about +y from +x, v = polar
/// angle θ/π from +y (v = 0 at the top).
class Sphere final : public Shape {
public:
    /// Throws std::invalid_argument for a radius that is not finite and positive.
    Sphere(const Vec3& center, float radius);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::shared_ptr<Shape> from_params(const ParamTable& params, const BuildContext& context);

    [[nodiscard]] Bounds3 bounds() const override;
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    /// All lanes at once (the roots' arithmetic without branches, vectorised across lanes).
    [[nodiscard]] uint32_t occluded_packet(const RayPacket& packet) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] float area() const override;
    [[nodiscard]] std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override;
    /// From outside: uniform over the cone of directions the sphere subtends (pbrt-v4 §6.2.4),
    /// so every sample hits the visible cap; from inside: uniform over the area.
    [[nodiscard]] std::optional<ShapeSample> sample_toward(
        const Vec3& ref, Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] float pdf_toward(const Vec3& ref, const Vec3& p, const Vec3& n) const override;
    [[nodiscard]] std::size_t memory_bytes() const override { return sizeof(*this); }
    [[nodiscard]] std::string_view type_name() const override { return "sphere"; }

    [[nodiscard]] const Vec3& center() const { return center_; }
    [[nodiscard]] float radius() const { return radius_; }

private:
    /// Sphere uv of a unit direction from the centre.
    [[nodiscard]] static Vec2 uv_of(const Vec3& n);
    /// Both roots of |o + t·d - c|² = r², ordered; false if the ray misses.
    bool roots(const Ray& ray, float& t_near, float& t_far) const;

    Vec3 center_;
    float radius_;
};

}  // namespace glint
