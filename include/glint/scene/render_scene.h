#pragma once
/// \file What the integrators read: a scene prepared for rendering. Made once from a
/// Scene description, which it keeps read-only once its singly placed meshes are in world
/// space (Scene::place_meshes_in_world); to render a changed scene, prepare the changed
/// description again. Integrators take nothing else, so nothing can be rendered
/// unprepared and no change after preparing can be silently ignored.

#include "glint/accel/ray_packet.h"
#include "glint/accel/wide_bvh.h"
#include "glint/lights/area_light.h"
#include "glint/lights/environment_light.h"
#include "glint/math/matrix3x4.h"
#include "glint/scene/scene.h"

#include <memory>
#include <vector>

namespace glint {

/// Counts for `glint info` and the final render line.
struct SceneStatistics {
    std::size_t objects = 0;
    std::size_t unique_shapes = 0;
    std::size_t unique_triangles = 0;     ///< triangles stored
    std::size_t instanced_triangles = 0;  ///< triangles as placed in the world
    std::size_t memory_bytes = 0;         ///< shapes + acceleration structures
};

class RenderScene {
public:
    /// Build every shape's own structure (in parallel), the area lights, and the top-level
    /// BVH over the objects (pbrt-v4's BasicScene → aggregate and lights).
    explicit RenderScene(Scene description);
    RenderScene(RenderScene&&) noexcept;
    RenderScene& operator=(RenderScene&&) noexcept;
    ~RenderScene();

    /// The description this was prepared from.
    [[nodiscard]] const Scene& description() const { return scene_; }
    [[nodiscard]] const Camera& camera() const { return scene_.camera; }
    [[nodiscard]] const Background& background() const { return scene_.background; }
    [[nodiscard]] const Color& ambient_light() const { return scene_.ambient_light; }
    [[nodiscard]] float ambient_ior() const { return scene_.ambient_ior; }
    [[nodiscard]] DielectricShadows dielectric_shadows() const { return scene_.dielectric_shadows; }
    [[nodiscard]] const Material& material(uint32_t index) const { return scene_.material(index); }

    /// Area lights: the declared ones and, with `emission_lights`, every emissive object
    /// whose shape has an area.
    [[nodiscard]] const std::vector<std::unique_ptr<AreaLight>>& area_lights() const { return area_lights_; }
    /// Every light, point-like first, then area lights, then the environment.
    [[nodiscard]] const std::vector<const Light*>& all_lights() const { return all_lights_; }
    /// The background as a light (the last of all_lights()); null when it is black.
    [[nodiscard]] const EnvironmentLight* environment_light() const { return environment_light_.get(); }
    /// Scene::environment_lighting: the Whitted integrator samples environment_light() too.
    [[nodiscard]] bool environment_lighting() const { return scene_.environment_lighting; }
    /// The area light that object `object` is, if any.
    [[nodiscard]] const AreaLight* area_light_of(uint32_t object) const {
        const int32_t i = objects_[object].area_light;
        return i < 0 ? nullptr : area_lights_[std::size_t(i)].get();
    }

    /// Closest hit in world space; fills hit.object too.
    bool intersect(Ray& ray, Hit& hit) const;
    /// Any hit that blocks light (dielectrics per `dielectric_shadows`, alpha cut-outs skipped).
    [[nodiscard]] bool occluded(const Ray& ray) const { return occluded(ray, scene_.dielectric_shadows); }
    /// Any hit that blocks light, with dielectrics treated as `mode` says.
    [[nodiscard]] bool occluded(const Ray& ray, DielectricShadows mode) const;
    /// intersect() and occluded() for the active lanes of a packet of rays
    /// (accel/ray_packet.h): return the lanes that hit; intersect_packet() shrinks their tmax
    /// and fills their hits, object included. Each lane gets what intersect() or occluded()
    /// would give its ray (at a tie of two surfaces at one t, possibly the other). Coherent
    /// packets (neighbouring camera rays, shadow rays toward one light) trace faster together
    /// than one by one (render_scene_packets.cpp).
    uint32_t intersect_packet(RayPacket& packet, PacketHits& hits) const;
    [[nodiscard]] uint32_t occluded_packet(const RayPacket& packet) const {
        return occluded_packet(packet, scene_.dielectric_shadows);
    }
    [[nodiscard]] uint32_t occluded_packet(const RayPacket& packet, DielectricShadows mode) const;
    /// Whether camera rays and the first hits' shadow rays toward point lights trace faster
    /// here as packets than one by one: some object's shape traces packets together (a mesh
    /// through its BVH). Analytic shapes take those packets at some cost, even under a top
    /// level of many objects (glint-scene-bench: shadow-ray packets rendered spheres.toml 5 %
    /// slower). An area light's samples from one point pay in every scene: their rays share
    /// their way and their time (docs/performance.md).
    [[nodiscard]] bool packets_pay() const { return packets_pay_; }
    /// intersect() and occluded() that also count the nodes and primitives they test (the
    /// viewer's heatmaps); same results.
    bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const;
    [[nodiscard]] bool occluded_counted(const Ray& ray, DielectricShadows mode, TraversalStats& stats) const;
    /// World-space surface description of a hit returned by intersect().
    [[nodiscard]] SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;
    /// Radiance that the surface of the object hit emits towards `wo` (unit, away from the
    /// surface): its area light's, or the material's emission where it is no light.
    /// Inline for the common case, a hit on something that emits nothing.
    [[nodiscard]] Color emitted(uint32_t object, const Material& m, const SurfaceInteraction& si,
                                const Vec3& wo) const {
        if (objects_[object].area_light < 0 && m.emission.is_black()) return Color();
        return emitted_slow(object, m, si, wo);
    }

    /// World bounds of all objects.
    [[nodiscard]] Bounds3 bounds() const { return top_level_.bounds(); }
    [[nodiscard]] SceneStatistics statistics() const;
    /// Whether camera rays need a time: something moves (Scene::has_motion). A scene where
    /// nothing moves draws no time sample, so a shutter changes none of its pixels.
    [[nodiscard]] bool has_motion() const { return has_motion_; }
    /// Whether a hit's texture coordinates are ever read: some material has a texture
    /// (Material::has_textures). Without, interaction() leaves them out (InteractionDetail)
    /// and the integrators follow no ray cones for texture footprints.
    [[nodiscard]] bool reads_texture_coordinates() const { return detail_ == InteractionDetail::Full; }

private:
    /// What a ray query needs of an object, packed for the top-level traversal; the rest
    /// (world_from_object, name) stays in the description.
    struct HotObject {
        const Shape* shape = nullptr;
        /// Set for a moving object: object_from_world is then made at each ray's time.
        const AnimatedTransform* motion = nullptr;
        /// Valid when `transformed`: rays go into object space by this (t is kept).
        Matrix3x4 object_from_world;
        bool transformed = false;
        /// Its material is a dielectric (for shadow rays under DielectricShadows::None).
        bool dielectric = false;
        /// Index into area_lights_ (−1: none).
        int32_t area_light = -1;
    };

    void build_area_lights();
    [[nodiscard]] Color emitted_slow(uint32_t object, const Material& m, const SurfaceInteraction& si,
                                     const Vec3& wo) const;
    bool intersect_object(uint32_t object, Ray& ray, Hit& hit) const;
    bool occluded_by_object(uint32_t object, const Ray& ray, DielectricShadows mode) const;
    /// Object `object`'s part of intersect(): `shape_intersect(shape, ray)` in its space.
    template <class ShapeIntersect>
    bool intersect_object_with(uint32_t object, Ray& ray, Hit& hit, const ShapeIntersect& shape_intersect) const;
    /// `visit(object, ray) -> bool` for the objects the ray may hit: through the top level,
    /// or, in a scene of at most kFewObjects objects, each object whose box the ray enters
    /// (each entered box counted as a node). With AnyHit, stops at the first object that
    /// reports a hit.
    template <bool AnyHit, class Visit, class Count = NoTraversalCount>
    bool visit_objects(Ray& ray, Visit&& visit, const Count& count = {}) const;
    /// The packet queries' parts for one object, for the lanes in `lanes`.
    uint32_t intersect_object_packet(uint32_t object, RayPacket& packet, uint32_t lanes, PacketHits& hits) const;
    [[nodiscard]] uint32_t occluded_by_object_packet(uint32_t object, const RayPacket& packet, uint32_t lanes,
                                                     DielectricShadows mode) const;
    /// visit_objects() for a packet: `visit(object, packet, lanes) -> uint32_t` (the lanes
    /// it hit) for the objects some lane may hit; with AnyHit a lane that has hit stops.
    template <bool AnyHit, class Visit>
    uint32_t visit_objects_packet(RayPacket& packet, Visit&& visit) const;

    /// Up to this many objects, a loop over them beats the top-level BVH: measured with
    /// glint-scene-bench, one- and two-object scenes rendered 4-14 % slower through it.
    static constexpr std::size_t kFewObjects = 4;

    Scene scene_;
    std::vector<HotObject> objects_;
    std::vector<std::unique_ptr<AreaLight>> area_lights_;
    std::unique_ptr<EnvironmentLight> environment_light_;
    std::vector<const Light*> all_lights_;
    /// The objects' boxes in an 8-wide BVH; a leaf reference is the object's index.
    WideBvh top_level_;
    /// The objects with a box (some shape may be empty) and their world boxes, when there are
    /// few (kFewObjects).
    struct FewObject {
        Bounds3 box;
        uint32_t object;
    };
    std::vector<FewObject> few_objects_;
    bool has_motion_ = false;
    /// What interaction() asks of a shape: all of it, or without texture coordinates.
    InteractionDetail detail_ = InteractionDetail::Full;
    bool packets_pay_ = false;
};

}  // namespace glint
