#pragma once
/// \file The scene description: objects (shapes placed by transforms), materials, lights,
/// camera and background, as loaders and programs build it. Rendering reads the
/// RenderScene made from it (scene/render_scene.h), never the description itself.

#include "glint/geometry/shape.h"
#include "glint/lights/light.h"
#include "glint/materials/material.h"
#include "glint/materials/texture.h"
#include "glint/math/animated_transform.h"
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
    /// Identity unless has_transform. For a moving object: its first key's.
    Transform world_from_object;
    bool has_transform = false;
    /// Set for an object that moves (motion blur): world_from_object over time.
    std::optional<AnimatedTransform> motion;
    uint32_t material = 0;
    std::string name;
    /// Set for objects that are declared lights; others emit if their material does.
    std::optional<Emitter> emitter;

    /// World bounds, from the shape's object-space bounds; for a moving object, over all
    /// its keys' times.
    [[nodiscard]] Bounds3 world_bounds() const {
        if (motion) return motion->bounds(shape->bounds(), motion->keys().front().time, motion->keys().back().time);
        return has_transform ? world_from_object.bounds(shape->bounds()) : shape->bounds();
    }
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
    /// Whether the Whitted integrator lights surfaces with the background: light_samples
    /// shadow-tested samples of the environment light per shading point, as for an area
    /// light, so that an HDR sun casts shadows. Off, the background is only seen (and the
    /// ambient term stands for it). The path tracer always samples a non-black background.
    bool environment_lighting = false;

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
    /// Does object `object` light the scene: a declared area light, or (with
    /// `emission_lights`) an object whose material has an emission.
    [[nodiscard]] bool emits_light(const SceneObject& object) const;
    /// True if the scene has a light or an object that emits.
    [[nodiscard]] bool has_emitters() const;

    /// Place `shape` with `material`; several objects may share one shape (instancing).
    /// Returns the object's index; std::invalid_argument for a transform that is not affine.
    uint32_t add_object(std::shared_ptr<Shape> shape, uint32_t material,
                        const std::optional<Transform>& world_from_object = std::nullopt, std::string name = {});
    [[nodiscard]] const std::vector<SceneObject>& objects() const { return objects_; }
    /// Make object `object` move: world_from_object becomes `motion`'s first key. Throws
    /// std::invalid_argument for an object that lights the scene (emits_light): light
    /// sampling assumes lights stay put, as pbrt-v4's does. (One made a light afterwards, by
    /// turning emission_lights on, is seen but never sampled.)
    void set_motion(uint32_t object, AnimatedTransform motion);
    /// The same scene with fewer transforms: each triangle mesh that one still object alone
    /// places is carried into world space and the object's transform becomes the identity,
    /// so that no ray and no hit on it pays for a transform (pbrt-v4 likewise keeps only
    /// instanced meshes in object space). A mesh held elsewhere too is copied first;
    /// mirroring placements, which would turn the triangles' winding, and placements that
    /// would leave float range stay as they are. RenderScene does this first.
    void place_meshes_in_world();
    /// True if an object moves or the camera does: then camera rays need a time.
    [[nodiscard]] bool has_motion() const;
    /// Place `shape` as an area light emitting `emitter.radiance` (a black material of its
    /// own absorbs what reaches it). Returns the object's index.
    uint32_t add_area_light(std::shared_ptr<Shape> shape, const Emitter& emitter,
                            const std::optional<Transform>& world_from_object = std::nullopt, std::string name = {});

    /// World bounds of all objects.
    [[nodiscard]] Bounds3 world_bounds() const;

private:
    std::vector<Material> materials_;
    std::vector<std::unique_ptr<Texture>> textures_;
    std::vector<std::unique_ptr<Light>> lights_;
    std::vector<SceneObject> objects_;
};

}  // namespace glint
