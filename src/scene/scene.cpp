#include "glint/scene/scene.h"

#include "glint/geometry/triangle_mesh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace glint {

Scene::Scene() = default;
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;
Scene::~Scene() = default;

uint32_t Scene::add_material(Material material) {
    materials_.push_back(std::move(material));
    return static_cast<uint32_t>(materials_.size() - 1);
}

std::optional<uint32_t> Scene::find_material(std::string_view name) const {
    for (uint32_t i = 0; i < materials_.size(); ++i)
        if (materials_[i].name == name) return i;
    return std::nullopt;
}

const Texture* Scene::add_texture(std::unique_ptr<Texture> texture) {
    textures_.push_back(std::move(texture));
    return textures_.back().get();
}

std::size_t Scene::texture_count() const {
    return static_cast<std::size_t>(
        std::count_if(textures_.begin(), textures_.end(), [](const auto& t) { return !t->is_view(); }));
}

void Scene::add_light(std::unique_ptr<Light> light) { lights_.push_back(std::move(light)); }

uint32_t Scene::add_area_light(std::shared_ptr<Shape> shape, const Emitter& emitter,
                               const std::optional<Transform>& world_from_object, std::string name) {
    Material black;
    black.name = name.empty() ? "<area light>" : "<area light " + name + ">";
    black.diffuse = Color(0.0f);
    const uint32_t object =
        add_object(std::move(shape), add_material(std::move(black)), world_from_object, std::move(name));
    objects_[object].emitter = emitter;
    return object;
}

bool Scene::emits_light(const SceneObject& o) const {
    return o.emitter ||
           (emission_lights && o.material < materials_.size() && !materials_[o.material].emission.is_black());
}

bool Scene::has_emitters() const {
    return !lights_.empty() ||
           std::any_of(objects_.begin(), objects_.end(), [&](const SceneObject& o) { return emits_light(o); });
}

uint32_t Scene::add_object(std::shared_ptr<Shape> shape, uint32_t material,
                           const std::optional<Transform>& world_from_object, std::string name) {
    // The render scene keeps only the top rows of the inverse (Matrix3x4).
    if (world_from_object && !world_from_object->matrix().is_affine())
        throw std::invalid_argument("an object's transform must be affine (last row 0, 0, 0, 1)");
    SceneObject object;
    object.shape = std::move(shape);
    object.material = material;
    object.name = std::move(name);
    if (world_from_object && !world_from_object->is_identity()) {
        object.world_from_object = *world_from_object;
        object.has_transform = true;
    }
    objects_.push_back(std::move(object));
    return static_cast<uint32_t>(objects_.size() - 1);
}

void Scene::set_motion(uint32_t index, AnimatedTransform motion) {
    SceneObject& o = objects_.at(index);
    if (emits_light(o))
        throw std::invalid_argument(
            "an object that lights the scene cannot move (moving lights are not supported; with emission_lights = "
            "false its emission is only seen, and it may)");
    o.world_from_object = motion.keys().front().transform;
    o.has_transform = true;
    o.motion = std::move(motion);
}

void Scene::place_meshes_in_world() {
    std::unordered_map<const Shape*, uint32_t> placements;
    for (const SceneObject& o : objects_) ++placements[o.shape.get()];
    std::vector<SceneObject*> chosen;
    for (SceneObject& o : objects_)
        if (o.has_transform && !o.motion && placements[o.shape.get()] == 1 && !o.world_from_object.swaps_handedness() &&
            dynamic_cast<TriangleMesh*>(o.shape.get()))
            chosen.push_back(&o);
    tbb::parallel_for(size_t(0), chosen.size(), [&](size_t k) {
        SceneObject& o = *chosen[k];
        auto& mesh = static_cast<TriangleMesh&>(*o.shape);
        try {
            // Held by this scene alone, the mesh is carried where it is; held elsewhere too
            // (by the program that made it, say), it is copied first.
            if (o.shape.use_count() == 1)
                mesh.transform_vertices(o.world_from_object);
            else
                o.shape = mesh.placed(o.world_from_object);
        } catch (const std::invalid_argument&) {
            return;  // it would leave float range: it stays a placement
        }
        o.world_from_object = Transform();
        o.has_transform = false;
    });
}

bool Scene::has_motion() const {
    return camera.moves() ||
           std::any_of(objects_.begin(), objects_.end(), [](const SceneObject& o) { return o.motion; });
}

Bounds3 Scene::world_bounds() const {
    Bounds3 b;
    for (const SceneObject& o : objects_) b.extend(o.world_bounds());
    return b;
}

}  // namespace glint
