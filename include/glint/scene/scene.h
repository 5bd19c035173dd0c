#pragma once
/// \file The scene: objects (shapes placed by transforms), materials, lights, camera,
/// background, and the top-level acceleration structure built by prepare().

#include "glint/accel/bvh.h"
#include "glint/geometry/shape.h"
#include "glint/lights/area_light.h"
#include "glint/lights/light.h"
#include "glint/materials/material.h"
#include "glint/materials/texture.h"
#include "glint/math/transform.h"
#include "glint/scene/background.h"
#include "glint/scene/camera.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

/// Whether dielectrics (transparency > 0) block shadow rays.
enum class DielectricShadows {
    /// The handout's rule: shadow rays pass through dielectrics as if they were absent.
    None,
    /// Dielectrics cast shadows like opaque objects.
    Opaque,
};

/// What an explicitly declared area light emits (`[[lights]] type = "sphere"` and kin).
struct Emitter {
    Color radiance;
    bool two_sided = false;
};

/// One placement of a shape in the world.
struct SceneObject {
    std::shared_ptr<Shape> shape;
    Transform world_from_object;
    /// Its inverse, kept so that every ray query need not invert.
    Transform object_from_world;
    bool has_transform = false;
    uint32_t material = 0;
    std::string name;
    /// Set for objects that are declared lights; others emit if their material does.
    std::optional<Emitter> emitter;
    /// Index into Scene::area_lights() of the light this object is (−1: none); set by prepare().
    int32_t area_light = -1;
};

/// Counts for `glint info` and the final render line.
struct SceneStatistics {
    std::size_t objects = 0;
    std::size_t unique_shapes = 0;
    std::size_t unique_triangles = 0;     ///< triangles stored
    std::size_t instanced_triangles = 0;  ///< triangles as placed in the world
    std::size_t memory_bytes = 0;         ///< shapes + acceleration structures
};

class Scene {
public:
    Scene();
    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;
    ~Scene();

    Camera camera;
    Background background;
    /// La: the ambient light colour, times each material's ka.
    Color ambient_light{0.0f};
    /// Index of refraction of the space between objects (the bottom of the IOR stack).
    float ambient_ior = 1.0f;
    DielectricShadows dielectric_shadows = DielectricShadows::None;
    /// Whether objects whose material has an `emission` are area lights that light the
    /// scene (pbrt-v4's DiffuseAreaLight), or, when false, only seen by rays that hit them
    /// (Glint's first Whitted behaviour). Declared area lights are lights either way.
    bool emission_lights = true;

    /// Returns the new material's index.
    uint32_t add_material(Material material);
    /// Index of the material called `name`, if any.
    [[nodiscard]] std::optional<uint32_t> find_material(std::string_view name) const;
    [[nodiscard]] const Material& material(uint32_t index) const { return materials_[index]; }
    [[nodiscard]] const std::vector<Material>& materials() const { return materials_; }

    /// The scene owns its textures; materials point at them.
    const Texture* add_texture(std::unique_ptr<Texture> texture);
    /// Textures the scene declares; views of them (Texture::is_view) are not counted.
    [[nodiscard]] std::size_t texture_count() const;

    /// A point-like light (point, spot, directional).
    void add_light(std::unique_ptr<Light> light);
    /// The lights added with add_light().
    [[nodiscard]] const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
    /// Area lights: the declared ones and, with `emission_lights`, every emissive object
    /// whose shape has an area (valid after prepare()).
    [[nodiscard]] const std::vector<std::unique_ptr<AreaLight>>& area_lights() const { return area_lights_; }
    /// Every light, point-like first, then area lights (valid after prepare()).
    [[nodiscard]] const std::vector<const Light*>& all_lights() const { return all_lights_; }
    /// The area light that object `object` is, if any (valid after prepare()).
    [[nodiscard]] const AreaLight* area_light_of(uint32_t object) const {
        const int32_t i = object_lights_[object];
        return i < 0 ? nullptr : area_lights_[std::size_t(i)].get();
    }
    /// True if the scene has a light or an object that emits (before or after prepare()).
    [[nodiscard]] bool has_emitters() const;

    /// Place `shape` with `material`; several objects may share one shape (instancing).
    /// Returns the object's index. Invalidates prepare().
    uint32_t add_object(std::shared_ptr<Shape> shape, uint32_t material,
                        const std::optional<Transform>& world_from_object = std::nullopt, std::string name = {});
    [[nodiscard]] const std::vector<SceneObject>& objects() const { return objects_; }
    /// Place `shape` as an area light emitting `emitter.radiance` (a black material of its
    /// own absorbs what reaches it). Returns the object's index.
    uint32_t add_area_light(std::shared_ptr<Shape> shape, const Emitter& emitter,
                            const std::optional<Transform>& world_from_object = std::nullopt, std::string name = {});

    /// Build every shape's own structure (in parallel) and the top-level BVH over objects.
    /// Must be called after the last change and before any query.
    void prepare();
    [[nodiscard]] bool prepared() const { return prepared_; }

    /// Closest hit in world space; fills hit.object too.
    bool intersect(Ray& ray, Hit& hit) const;
    /// Any hit that blocks light (dielectrics per `dielectric_shadows`, alpha cut-outs skipped).
    [[nodiscard]] bool occluded(const Ray& ray) const { return occluded(ray, dielectric_shadows); }
    /// Any hit that blocks light, with dielectrics treated as `mode` says.
    [[nodiscard]] bool occluded(const Ray& ray, DielectricShadows mode) const;
    /// Radiance that the surface of the object hit emits towards `wo` (unit, away from the
    /// surface): its area light's, or the material's emission where it is no light.
    [[nodiscard]] Color emitted(uint32_t object, const Material& m, const SurfaceInteraction& si, const Vec3& wo) const;
    /// World-space surface description of a hit returned by intersect().
    [[nodiscard]] SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;

    /// World bounds of all objects (valid after prepare()).
    [[nodiscard]] Bounds3 bounds() const { return top_level_.bounds(); }
    [[nodiscard]] SceneStatistics statistics() const;

private:
    bool intersect_object(uint32_t object, Ray& ray, Hit& hit) const;
    bool occluded_by_object(uint32_t object, const Ray& ray, DielectricShadows mode) const;
    /// Does `o` emit light into the scene: a declared area light, or (with emission_lights)
    /// an object whose material has an emission.
    [[nodiscard]] bool lights_scene(const SceneObject& o) const;
    void build_area_lights();

    std::vector<Material> materials_;
    std::vector<std::unique_ptr<Texture>> textures_;
    std::vector<std::unique_ptr<Light>> lights_;
    std::vector<SceneObject> objects_;
    std::vector<std::unique_ptr<AreaLight>> area_lights_;
    std::vector<const Light*> all_lights_;
    /// Per object, its area light's index or −1: a compact copy of SceneObject::area_light
    /// for the lookup at every hit (a SceneObject is a few hundred bytes).
    std::vector<int32_t> object_lights_;
    /// Per object: is its material a dielectric (derived in prepare(), for shadow rays).
    std::vector<uint8_t> dielectric_;
    Bvh top_level_;
    bool prepared_ = false;
};

}  // namespace glint
