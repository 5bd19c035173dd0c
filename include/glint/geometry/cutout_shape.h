#pragma once
/// \file An analytic shape cut out by a material's alpha texture (TOML `alpha_texture` on a
/// sphere, quad, disk, box or heightfield). Triangle meshes test their mask inside their own
/// traversal (TriangleMesh::set_alpha_mask); this wrapper gives every other shape the same
/// behaviour without touching its intersection code.

#include "glint/geometry/shape.h"
#include "glint/materials/texture.h"

#include <memory>

namespace glint {

class CutoutShape final : public Shape {
public:
    /// Hits of `shape` where `alpha->alpha(uv) < cutoff` are skipped, by shadow rays too.
    CutoutShape(std::shared_ptr<Shape> shape, const Texture* alpha, float cutoff)
        : shape_(std::move(shape)), alpha_(alpha), cutoff_(cutoff) {}

    [[nodiscard]] Bounds3 bounds() const override { return shape_->bounds(); }
    /// The closest hit the mask keeps: a hit it cuts is stepped over and the ray goes on
    /// from just beyond it (a sphere's far side, a heightfield's next fold).
    bool intersect(Ray& ray, Hit& hit) const override;
    [[nodiscard]] bool occluded(const Ray& ray) const override;
    void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                     InteractionDetail detail = InteractionDetail::Full) const override {
        shape_->interaction(ray, hit, si, detail);
    }
    void prepare() override { shape_->prepare(); }
    /// Area and sampling are the whole shape's: a cut-out emitter is sampled where it is cut
    /// too (unbiased, but the samples there are wasted).
    [[nodiscard]] float area() const override { return shape_->area(); }
    [[nodiscard]] std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override {
        return shape_->sample_area(u, detail);
    }
    [[nodiscard]] std::optional<ShapeSample> sample_toward(
        const Vec3& ref, Vec2 u, InteractionDetail detail = InteractionDetail::Full) const override {
        return shape_->sample_toward(ref, u, detail);
    }
    [[nodiscard]] float pdf_toward(const Vec3& ref, const Vec3& p, const Vec3& n) const override {
        return shape_->pdf_toward(ref, p, n);
    }
    void prepare_sampling() override { shape_->prepare_sampling(); }
    [[nodiscard]] std::size_t primitive_count() const override { return shape_->primitive_count(); }
    [[nodiscard]] std::size_t triangle_count() const override { return shape_->triangle_count(); }
    [[nodiscard]] std::size_t memory_bytes() const override { return sizeof(*this) + shape_->memory_bytes(); }
    [[nodiscard]] std::string_view type_name() const override { return shape_->type_name(); }

private:
    std::shared_ptr<Shape> shape_;
    const Texture* alpha_;
    float cutoff_;
};

}  // namespace glint
