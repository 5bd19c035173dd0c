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
    /// The eight lanes at once (a floor under a mesh meets every packet of a render), each
    /// with what its ray gets alone, bit for bit.
    uint32_t intersect_packet(RayPacket& packet, PacketHits& hits) const override;
    [[nodiscard]] uint32_t occluded_packet(const RayPacket& packet) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] float area() const override { return area_; }
    [[nodiscard]] std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] std::size_t memory_bytes() const override { return sizeof(*this); }
    [[nodiscard]] std::string_view type_name() const override { return "quad"; }

private:
    /// The plane hit of one ray and its coordinates (a, b); whether t lies in (tmin, tmax)
    /// and (a, b) in the unit square. Without branches, so that the packet queries' loop
    /// over the lanes vectorises into the same arithmetic, hence the same bits.
    [[nodiscard]] bool hit_parameters(const Vec3& origin, const Vec3& direction, float tmin, float tmax, float& t,
                                      float& a, float& b) const;
    /// hit_parameters() of every lane of a packet.
    struct PacketHitParameters {
        alignas(32) float t[RayPacket::kSize];
        alignas(32) float a[RayPacket::kSize];
        alignas(32) float b[RayPacket::kSize];
        uint32_t lanes = 0;  ///< that hit, active or not
    };
    [[nodiscard]] PacketHitParameters hit_lanes(const RayPacket& packet) const;

    Vec3 corner_, edge_u_, edge_v_, normal_;
    /// edge_u × edge_v and 1 / |edge_u × edge_v|², the dual basis's scale.
    Vec3 cross_uv_;
    float inv_cross_uv2_ = 0.0f;
    float area_ = 0.0f;
};

}  // namespace glint
