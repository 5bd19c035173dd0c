#include "glint/scene/scene.h"

#include <tbb/parallel_for_each.h>

#include <algorithm>
#include <unordered_set>

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

void Scene::add_light(std::unique_ptr<Light> light) {
    lights_.push_back(std::move(light));
    prepared_ = false;
}

uint32_t Scene::add_area_light(std::shared_ptr<Shape> shape, const Emitter& emitter,
                               const std::optional<Transform>& world_from_object, std::string name) {
    Material black;
    black.name = name.empty() ? "<area light>" : "<area light " + name + ">";
    black.diffuse = Color(0.0f);
    const uint32_t object = add_object(std::move(shape), add_material(std::move(black)), world_from_object, std::move(name));
    objects_[object].emitter = emitter;
    return object;
}

bool Scene::lights_scene(const SceneObject& o) const {
    return o.emitter || (emission_lights && o.material < materials_.size() && !materials_[o.material].emission.is_black());
}

bool Scene::has_emitters() const {
    return !lights_.empty() || std::any_of(objects_.begin(), objects_.end(), [&](const SceneObject& o) { return lights_scene(o); });
}

void Scene::build_area_lights() {
    area_lights_.clear();
    for (SceneObject& o : objects_) {
        o.area_light = -1;
        const std::optional<Transform> transform =
            o.has_transform ? std::optional<Transform>(o.world_from_object) : std::nullopt;
        if (!lights_scene(o)) continue;
        if (o.emitter) {
            area_lights_.push_back(
                std::make_unique<AreaLight>(o.shape, transform, o.emitter->radiance, nullptr, o.emitter->two_sided));
        } else {
            o.shape->prepare_sampling();
            // A shape without area (a heightfield) keeps its emission visible only.
            if (!(o.shape->area() > 0.0f)) continue;
            const Material& m = materials_[o.material];
            // Glint's surfaces are two-sided, and so is what they emit.
            area_lights_.push_back(std::make_unique<AreaLight>(o.shape, transform, m.emission, m.emission_texture, true));
        }
        o.area_light = int32_t(area_lights_.size() - 1);
    }
    object_lights_.clear();
    for (const SceneObject& o : objects_) object_lights_.push_back(o.area_light);
    all_lights_.clear();
    for (const auto& l : lights_) all_lights_.push_back(l.get());
    for (const auto& l : area_lights_) all_lights_.push_back(l.get());
}

Color Scene::emitted(uint32_t object, const Material& m, const SurfaceInteraction& si, const Vec3& wo) const {
    if (const AreaLight* light = area_light_of(object)) return light->emitted(si.p, si.geometric_normal, si.uv, wo);
    Color le = m.emission;
    if (m.emission_texture) le *= m.emission_texture->evaluate(si.uv, si.p);
    return le;
}

uint32_t Scene::add_object(std::shared_ptr<Shape> shape, uint32_t material,
                           const std::optional<Transform>& world_from_object, std::string name) {
    SceneObject object;
    object.shape = std::move(shape);
    object.material = material;
    object.name = std::move(name);
    if (world_from_object && !world_from_object->is_identity()) {
        object.world_from_object = *world_from_object;
        object.object_from_world = world_from_object->inverse();
        object.has_transform = true;
    }
    objects_.push_back(std::move(object));
    prepared_ = false;
    return static_cast<uint32_t>(objects_.size() - 1);
}

void Scene::prepare() {
    std::vector<Shape*> unique;
    {
        std::unordered_set<Shape*> seen;
        for (const SceneObject& o : objects_)
            if (seen.insert(o.shape.get()).second) unique.push_back(o.shape.get());
    }
    tbb::parallel_for_each(unique.begin(), unique.end(), [](Shape* shape) { shape->prepare(); });

    std::vector<Bounds3> boxes(objects_.size());
    dielectric_.resize(objects_.size());
    for (size_t i = 0; i < objects_.size(); ++i) {
        const SceneObject& o = objects_[i];
        boxes[i] = o.has_transform ? o.world_from_object.bounds(o.shape->bounds()) : o.shape->bounds();
        dielectric_[i] = o.material < materials_.size() && materials_[o.material].is_dielectric();
    }
    build_area_lights();
    // Top level: few, large primitives; one per leaf keeps every object test behind a box test.
    BvhBuildConfig config;
    config.max_leaf_size = 1;
    top_level_.build(boxes, config);
    prepared_ = true;
}

bool Scene::intersect_object(uint32_t index, Ray& ray, Hit& hit) const {
    const SceneObject& o = objects_[index];
    if (!o.has_transform) {
        if (!o.shape->intersect(ray, hit)) return false;
    } else {
        // Transform the ray into object space without renormalising: t is the same in both.
        Ray local = o.object_from_world.ray(ray);
        if (!o.shape->intersect(local, hit)) return false;
        ray.tmax = local.tmax;
    }
    hit.object = index;
    return true;
}

bool Scene::occluded_by_object(uint32_t index, const Ray& ray, DielectricShadows mode) const {
    if (dielectric_[index] && mode == DielectricShadows::None) return false;
    const SceneObject& o = objects_[index];
    return o.has_transform ? o.shape->occluded(o.object_from_world.ray(ray)) : o.shape->occluded(ray);
}

bool Scene::intersect(Ray& ray, Hit& hit) const {
    return top_level_.traverse<false>(ray, [&](uint32_t object, Ray& r) { return intersect_object(object, r, hit); });
}

bool Scene::occluded(const Ray& ray, DielectricShadows mode) const {
    Ray r = ray;
    return top_level_.traverse<true>(r, [&](uint32_t object, Ray& rr) { return occluded_by_object(object, rr, mode); });
}

SurfaceInteraction Scene::interaction(const Ray& ray, const Hit& hit) const {
    const SceneObject& o = objects_[hit.object];
    SurfaceInteraction si;
    if (!o.has_transform) {
        o.shape->interaction(ray, hit, si);
    } else {
        o.shape->interaction(o.object_from_world.ray(ray), hit, si);
        si.p = o.world_from_object.point(si.p);
        si.geometric_normal = normalize(o.world_from_object.normal(si.geometric_normal));
        si.shading_normal = normalize(o.world_from_object.normal(si.shading_normal));
        si.front_face = dot(ray.direction, si.geometric_normal) < 0.0f;
    }
    if (!si.blends_materials) si.materials[0] = o.material;
    return si;
}

SceneStatistics Scene::statistics() const {
    SceneStatistics s;
    s.objects = objects_.size();
    std::unordered_set<const Shape*> seen;
    for (const SceneObject& o : objects_) {
        s.instanced_triangles += o.shape->triangle_count();
        if (seen.insert(o.shape.get()).second) {
            ++s.unique_shapes;
            s.unique_triangles += o.shape->triangle_count();
            s.memory_bytes += o.shape->memory_bytes();
        }
    }
    s.memory_bytes += top_level_.memory_bytes() + objects_.size() * sizeof(SceneObject);
    return s;
}

}  // namespace glint
