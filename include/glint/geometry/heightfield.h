#pragma once
/// \file Heightfield: a regular grid of heights, traversed cell by cell.

#include "glint/geometry/shape.h"
#include "glint/geometry/triangle.h"
#include "glint/math/vec2.h"

#include <vector>

namespace glint {

/// Heights y(i, j) over a regular nx × nz grid of vertices spanning [x0, x1] × [z0, z1]
/// (the handout's water surface). Each cell is split into two triangles. Rays walk the
/// cells they cross in 2D (Amanatides & Woo 1987, "A Fast Voxel Traversal Algorithm")
/// and stop at the first cell that yields a hit, so a query costs O(cells crossed); each
/// cell's triangles get meshes' watertight test, so no ray slips through a shared edge.
/// Normals are interpolated from central differences; uv = position within the extent.
class Heightfield final : public Shape {
public:
    /// `heights` holds nx·nz values, row by row (x fastest). Throws std::invalid_argument
    /// for fewer than 2×2 vertices, a size mismatch, an empty extent or a non-finite height.
    Heightfield(uint32_t nx, uint32_t nz, std::vector<float> heights, Vec2 min_xz, Vec2 max_xz);
    /// The scene-file factory (docs/scene-format.md): reads its keys, throws SceneError at a bad one.
    [[nodiscard]] static std::shared_ptr<Shape> from_params(const ParamTable& params, const BuildContext& context);

    [[nodiscard]] Bounds3 bounds() const override { return bounds_; }
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override;
    [[nodiscard]] std::size_t primitive_count() const override { return 2u * (nx_ - 1) * (nz_ - 1); }
    /// Two per cell, as primitive_count().
    [[nodiscard]] std::size_t triangle_count() const override { return primitive_count(); }
    [[nodiscard]] std::size_t memory_bytes() const override;
    [[nodiscard]] std::string_view type_name() const override { return "heightfield"; }

    [[nodiscard]] float height(uint32_t i, uint32_t j) const { return heights_[j * nx_ + i]; }

private:
    /// Closest hit: the first cell along the ray that yields one (also serves any-hit).
    bool traverse(Ray& ray, Hit& hit) const;
    bool intersect_cell(uint32_t i, uint32_t j, const WatertightRay& shear, Ray& ray, Hit& hit) const;
    [[nodiscard]] Vec3 vertex(uint32_t i, uint32_t j) const;
    [[nodiscard]] Vec3 vertex_normal(uint32_t i, uint32_t j) const;

    uint32_t nx_, nz_;
    std::vector<float> heights_;
    Vec2 min_, max_;
    Vec2 cell_size_;
    Bounds3 bounds_;
};

}  // namespace glint
