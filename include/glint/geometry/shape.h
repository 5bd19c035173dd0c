#pragma once
/// \file The interface every kind of geometry implements.

#include "glint/geometry/hit.h"
#include "glint/math/bounds3.h"
#include "glint/math/ray.h"

#include <cstddef>
#include <string_view>

namespace glint {

/// A shape lives in its own object space; the scene places it with a transform
/// (several placements of one shape share its data: instancing). A shape with
/// many primitives (a mesh) keeps its own acceleration structure, built in
/// prepare(), so the scene-level structure never calls a shape per triangle.
class Shape {
public:
    virtual ~Shape() = default;

    /// Bounds in object space. Valid before prepare().
    [[nodiscard]] virtual Bounds3 bounds() const = 0;

    /// Closest hit with t in [ray.tmin, ray.tmax]. On a hit, sets ray.tmax = hit.t, fills
    /// hit.t, hit.primitive, hit.u, hit.v (not hit.object) and returns true.
    virtual bool intersect(Ray& ray, Hit& hit) const = 0;

    /// Any hit with t in [ray.tmin, ray.tmax]: the shadow-ray query, which may stop early.
    [[nodiscard]] virtual bool occluded(const Ray& ray) const = 0;

    /// Full surface description in object space for a hit this shape reported.
    /// `si.materials` is left to the caller unless the shape has per-vertex materials.
    virtual void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si) const = 0;

    /// Build internal acceleration data. Called once by Scene::prepare(), possibly in parallel
    /// with other shapes' prepare().
    virtual void prepare() {}

    [[nodiscard]] virtual std::size_t primitive_count() const { return 1; }
    /// Bytes of geometry and acceleration data this shape owns.
    [[nodiscard]] virtual std::size_t memory_bytes() const = 0;
    [[nodiscard]] virtual std::string_view type_name() const = 0;
};

}  // namespace glint
