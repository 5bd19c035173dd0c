#pragma once
/// \file The interface every kind of geometry implements.

#include "glint/accel/ray_packet.h"
#include "glint/accel/traversal_count.h"
#include "glint/geometry/hit.h"
#include "glint/math/bounds3.h"
#include "glint/math/ray.h"
#include "glint/math/vec2.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>

namespace glint {

class BuildContext;
class ParamTable;

/// A point on a shape's surface chosen for light sampling, in the shape's object space.
struct ShapeSample {
    Vec3 p;
    /// Unit normal on the side the shape calls outside.
    Vec3 n;
    /// Texture coordinates; (0, 0) when sampled with InteractionDetail::WithoutTextureCoordinates
    /// by a shape whose coordinates cost something (a sphere's: an atan2 and an acos).
    Vec2 uv;
    /// Density of the choice: per unit area (sample_area) or per unit solid angle at the
    /// receiving point (sample_toward).
    float pdf = 0.0f;
};

/// How much of a SurfaceInteraction a caller needs, as Mitsuba 3's RayFlags let a caller ask
/// for less. Texture coordinates, ∂p/∂u, ∂p/∂v, the tangent and the curvature serve only
/// texture lookups (and the ray cones that size them), so a scene without textures never
/// reads them; a sphere pays an atan2 and an acos for its uv.
enum class InteractionDetail {
    /// Everything SurfaceInteraction holds.
    Full,
    /// The point, normals, side, vertex colour and materials; the shape may leave uv, dpdu,
    /// dpdv, tangent and curvature at their defaults.
    WithoutTextureCoordinates,
};

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

    /// intersect() and occluded() for the active lanes of a packet (accel/ray_packet.h):
    /// return the lanes that hit; intersect_packet() shrinks their tmax and fills their
    /// hits (all but the object). Each lane gets what its ray would get alone (at a tie of
    /// two primitives at one t, possibly the other). The defaults take the lanes one by
    /// one; a mesh traces them together, a quad (and a sphere's occluded_packet) tests them
    /// in a few SIMD operations.
    virtual uint32_t intersect_packet(RayPacket& packet, PacketHits& hits) const;
    [[nodiscard]] virtual uint32_t occluded_packet(const RayPacket& packet) const;
    /// Whether the packet queries trace the lanes together through a structure they share
    /// (a mesh's BVH), so that a scene with this shape renders faster in packets. A quad
    /// takes its lanes at once too, but in a few SIMD operations that cost what single rays
    /// do: scenes of quads and spheres render no faster in packets (docs/performance.md).
    [[nodiscard]] virtual bool traces_packets() const { return false; }

    /// intersect() and occluded() that also count what they test, for the viewer's heatmaps
    /// (accel/traversal_count.h). An analytic shape is one primitive; a mesh counts its
    /// nodes and triangles.
    virtual bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
        ++stats.primitives;
        return intersect(ray, hit);
    }
    [[nodiscard]] virtual bool occluded_counted(const Ray& ray, TraversalStats& stats) const {
        ++stats.primitives;
        return occluded(ray);
    }

    /// Full surface description in object space for a hit this shape reported (with
    /// `detail`, possibly less: see InteractionDetail). `si.materials` is left to the caller
    /// unless the shape has per-vertex materials.
    virtual void interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si,
                             InteractionDetail detail = InteractionDetail::Full) const = 0;

    /// Build internal acceleration data. Called once by Scene::prepare(), possibly in parallel
    /// with other shapes' prepare().
    virtual void prepare() {}

    /// Surface area in object space; 0 for a shape that cannot be sampled (it cannot be an
    /// area light; its emission is then only seen).
    [[nodiscard]] virtual float area() const { return 0.0f; }
    /// A point uniformly distributed over the surface (pdf = 1/area per unit area). With
    /// InteractionDetail::WithoutTextureCoordinates the shape may leave uv at (0, 0): an
    /// untextured light never reads it.
    [[nodiscard]] virtual std::optional<ShapeSample> sample_area(
        Vec2 u, InteractionDetail detail = InteractionDetail::Full) const {
        (void)u;
        (void)detail;
        return std::nullopt;
    }
    /// A point as seen from `ref`, with its density per unit solid angle at `ref`. The
    /// default converts area sampling: pdf_ω = pdf_A·d²/|cos θ_light| (pbrt-v4 §6.1.4);
    /// shapes with a better strategy (spheres: the cone they subtend) override it.
    [[nodiscard]] virtual std::optional<ShapeSample> sample_toward(
        const Vec3& ref, Vec2 u, InteractionDetail detail = InteractionDetail::Full) const;
    /// The density sample_toward(ref, ·) has at the surface point p with unit normal n.
    [[nodiscard]] virtual float pdf_toward(const Vec3& ref, const Vec3& p, const Vec3& n) const;
    /// Build what sampling needs (a mesh's triangle distribution); called once before a
    /// shape serves as an area light.
    virtual void prepare_sampling() {}

    [[nodiscard]] virtual std::size_t primitive_count() const { return 1; }
    /// Triangles the shape stores (meshes, heightfields); 0 for analytic shapes.
    [[nodiscard]] virtual std::size_t triangle_count() const { return 0; }
    /// Bytes of geometry and acceleration data this shape owns.
    [[nodiscard]] virtual std::size_t memory_bytes() const = 0;
    [[nodiscard]] virtual std::string_view type_name() const = 0;
};

}  // namespace glint
