#pragma once
/// \file Indexed triangle mesh: flat arrays plus its own 8-wide BVH (the bottom level).

#include "glint/accel/triangle_bvh.h"
#include "glint/geometry/shape.h"
#include "glint/geometry/tangent_space.h"
#include "glint/materials/texture.h"
#include "glint/math/transform.h"
#include "glint/math/vec2.h"
#include "glint/sampling/discrete_distribution.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {

/// The data of a triangle mesh, as loaders produce it. Optional arrays are either empty
/// or have one entry per vertex.
struct MeshData {
    std::vector<Vec3> positions;
    /// Three vertex indices per triangle, counter-clockwise seen from the front.
    std::vector<uint32_t> indices;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    /// Per-vertex colours (PLY red/green/blue, OBJ "v x y z r g b"), linear: they multiply
    /// the material's base colour at a hit, interpolated with barycentrics.
    std::vector<Color> colors;
    /// Per-vertex scene material indices, blended with barycentrics at a hit (handout §6.1.1).
    std::vector<uint32_t> vertex_materials;
    /// Per-vertex tangent frames for normal maps (geometry/tangent_space.h); a mesh with
    /// normals and texture coordinates computes them when none are given.
    std::vector<Tangent> tangents;
};

/// Fill `data.normals` with smooth vertex normals: at each vertex, the sum of the unnormalised
/// normals (e1 × e2, so weighted by area) of the triangles that share it, normalised. Only
/// triangles that share a vertex index are smoothed together: meshes whose faces have
/// their own vertices (STL) stay faceted.
void compute_smooth_normals(MeshData& data);

/// A mesh is stored once and may be placed by several scene objects (instancing).
/// Zero-area triangles are kept but never reported as hits.
class TriangleMesh final : public Shape {
public:
    /// Validates the data; throws std::invalid_argument naming the problem (index out of
    /// range, array size mismatch, non-finite position, no triangles).
    explicit TriangleMesh(MeshData data, std::string name = {});
    /// The scene-file factories (docs/scene-format.md, src/geometry/triangle_mesh_params.cpp):
    /// `type = "mesh"` with inline positions and indices, and `type = "triangle"`. Each
    /// reads its keys and throws SceneError at a bad one.
    [[nodiscard]] static std::shared_ptr<Shape> from_params(const ParamTable& params, const BuildContext& context);
    [[nodiscard]] static std::shared_ptr<Shape> triangle_from_params(const ParamTable& params,
                                                                     const BuildContext& context);

    [[nodiscard]] Bounds3 bounds() const override { return bounds_; }
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    /// Packets through the BVH together; with an alpha mask, lane by lane.
    uint32_t intersect_packet(RayPacket& packet, PacketHits& hits) const override;
    [[nodiscard]] uint32_t occluded_packet(const RayPacket& packet) const override;
    [[nodiscard]] bool traces_packets() const override { return !has_alpha_mask(); }
    bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override;
    [[nodiscard]] bool occluded_counted(const Ray& ray, TraversalStats& stats) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override;
    void prepare() override;
    [[nodiscard]] float area() const override;
    /// A triangle chosen by area (needs prepare_sampling()), then a uniform point in it.
    [[nodiscard]] std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override;
    void prepare_sampling() override;
    [[nodiscard]] std::size_t primitive_count() const override { return triangle_count(); }
    [[nodiscard]] std::size_t memory_bytes() const override;
    [[nodiscard]] std::string_view type_name() const override { return "mesh"; }

    [[nodiscard]] std::size_t triangle_count() const override { return data_.indices.size() / 3; }
    [[nodiscard]] const MeshData& data() const { return data_; }
    [[nodiscard]] const std::string& name() const { return name_; }
    /// The bottom-level structure (empty before prepare()).
    [[nodiscard]] const TriangleBvh& bvh() const { return bvh_; }

    /// Cut-out mask (glTF alphaMode MASK): hits where `alpha->alpha(uv) < cutoff` are
    /// skipped by every query, shadow rays too. Needs uvs; null removes the mask.
    void set_alpha_mask(const Texture* alpha, float cutoff) { alpha_mask_ = alpha; alpha_cutoff_ = cutoff; }
    [[nodiscard]] const Texture* alpha_mask() const { return alpha_mask_; }

    /// Carries the mesh by `world_from_object` (affine; one that mirrors would turn the
    /// triangles' winding, so callers keep those as placements): positions, and normals and
    /// tangents turned with them. Drops the BVH and the sampling table, which prepare() and
    /// prepare_sampling() make again. Throws std::invalid_argument, leaving the mesh as it
    /// was, where a position would leave float range.
    void transform_vertices(const Transform& world_from_object);
    /// A copy of this mesh, alpha mask included, carried by transform_vertices().
    [[nodiscard]] std::shared_ptr<TriangleMesh> placed(const Transform& world_from_object) const;

    /// Test one triangle with the watertight test, alpha mask included: the scalar
    /// reference for the BVH's SIMD leaves (brute-force tests call it).
    bool intersect_triangle(uint32_t triangle, Ray& ray, Hit& hit) const;

private:
    /// The mask applies only to meshes with texture coordinates.
    [[nodiscard]] bool has_alpha_mask() const { return alpha_mask_ != nullptr && !data_.uvs.empty(); }
    /// Whether the alpha mask keeps the hit at barycentrics (b1, b2) of `triangle`.
    [[nodiscard]] bool passes_alpha(uint32_t triangle, float b1, float b2) const;

    MeshData data_;
    std::string name_;
    Bounds3 bounds_;
    TriangleBvh bvh_;
    /// Triangles by area, for sampling the mesh as an area light (empty until needed).
    std::optional<DiscreteDistribution> triangle_areas_;
    const Texture* alpha_mask_ = nullptr;
    float alpha_cutoff_ = 0.5f;
};

}  // namespace glint
