#include "glint/scene/render_scene.h"

#include <tbb/parallel_for_each.h>

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace glint {

RenderScene::RenderScene(Scene description) : scene_(std::move(description)) {
    scene_.place_meshes_in_world();
    const std::vector<SceneObject>& objects = scene_.objects();
    std::vector<Shape*> unique;
    {
        std::unordered_set<Shape*> seen;
        for (const SceneObject& o : objects)
            if (seen.insert(o.shape.get()).second) unique.push_back(o.shape.get());
    }
    tbb::parallel_for_each(unique.begin(), unique.end(), [](Shape* shape) { shape->prepare(); });

    std::vector<Bounds3> boxes(objects.size());
    objects_.resize(objects.size());
    for (size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& o = objects[i];
        HotObject& hot = objects_[i];
        hot.shape = o.shape.get();
        if (o.has_transform) {
            hot.object_from_world = Matrix3x4::of(o.world_from_object.inverse_matrix());
            hot.transformed = true;
        }
        hot.dielectric = o.material < scene_.materials().size() && scene_.material(o.material).is_dielectric();
        if (o.motion) {
            // The top level bounds a moving object over the time the shutter is open
            // (pbrt-v4's AnimatedTransform::MotionBounds).
            hot.motion = &*o.motion;
            const Shutter& shutter = scene_.camera.shutter();
            boxes[i] = o.motion->bounds(o.shape->bounds(), shutter.open, shutter.close);
        } else {
            boxes[i] = o.world_bounds();
        }
    }
    has_motion_ = scene_.has_motion();
    detail_ = std::ranges::any_of(scene_.materials(), &Material::has_textures)
                  ? InteractionDetail::Full
                  : InteractionDetail::WithoutTextureCoordinates;
    packets_pay_ = std::any_of(objects_.begin(), objects_.end(),
                               [](const HotObject& o) { return o.shape && o.shape->traces_packets(); });
    build_area_lights();
    // Top level: few, large primitives; one per leaf keeps every object test behind a box
    // test, and the leaf reference becomes the object's index.
    BvhBuildConfig config;
    config.max_leaf_size = 1;
    top_level_.build(boxes, config);
    const std::vector<WideLeaf> leaves(top_level_.leaves().begin(), top_level_.leaves().end());
    const std::vector<uint32_t> order(top_level_.primitive_order().begin(), top_level_.primitive_order().end());
    top_level_.encode_leaves([&](uint32_t leaf) { return order[leaves[leaf].first]; });
    if (order.size() <= kFewObjects)
        for (const uint32_t object : order) few_objects_.push_back({boxes[object], object});
}

RenderScene::RenderScene(RenderScene&&) noexcept = default;
RenderScene& RenderScene::operator=(RenderScene&&) noexcept = default;
RenderScene::~RenderScene() = default;

void RenderScene::build_area_lights() {
    const std::vector<SceneObject>& objects = scene_.objects();
    for (size_t i = 0; i < objects.size(); ++i) {
        const SceneObject& o = objects[i];
        // A moving object is never a light (Scene::set_motion).
        if (!scene_.emits_light(o) || o.motion) continue;
        const std::optional<Transform> transform =
            o.has_transform ? std::optional<Transform>(o.world_from_object) : std::nullopt;
        if (o.emitter) {
            area_lights_.push_back(
                std::make_unique<AreaLight>(o.shape, transform, o.emitter->radiance, nullptr, o.emitter->two_sided));
        } else {
            o.shape->prepare_sampling();
            // A shape without area (a heightfield) keeps its emission visible only.
            if (!(o.shape->area() > 0.0f)) continue;
            const Material& m = scene_.material(o.material);
            // Glint's surfaces are two-sided, and so is what they emit.
            area_lights_.push_back(
                std::make_unique<AreaLight>(o.shape, transform, m.emission, m.emission_texture, true));
        }
        objects_[i].area_light = int32_t(area_lights_.size() - 1);
    }
    for (const auto& l : scene_.lights()) all_lights_.push_back(l.get());
    for (const auto& l : area_lights_) all_lights_.push_back(l.get());
    environment_light_ = EnvironmentLight::of(scene_.background);
    if (environment_light_) all_lights_.push_back(environment_light_.get());
}

Color RenderScene::emitted_slow(uint32_t object, const Material& m, const SurfaceInteraction& si,
                                const Vec3& wo) const {
    if (const AreaLight* light = area_light_of(object)) return light->emitted(si.p, si.geometric_normal, si.uv, wo);
    Color le = m.emission;
    if (m.emission_texture) le *= m.emission_texture->evaluate(TextureQuery{si.uv, si.p, si.uv_footprint});
    return le;
}

template <class ShapeIntersect>
bool RenderScene::intersect_object_with(uint32_t index, Ray& ray, Hit& hit,
                                        const ShapeIntersect& shape_intersect) const {
    const HotObject& o = objects_[index];
    if (o.motion) {
        Ray local = o.motion->at(ray.time).inverse().ray(ray);
        if (!shape_intersect(*o.shape, local)) return false;
        ray.tmax = local.tmax;
    } else if (!o.transformed) {
        if (!shape_intersect(*o.shape, ray)) return false;
    } else {
        // Transform the ray into object space without renormalising: t is the same in both.
        Ray local = o.object_from_world.ray(ray);
        if (!shape_intersect(*o.shape, local)) return false;
        ray.tmax = local.tmax;
    }
    hit.object = index;
    return true;
}

bool RenderScene::intersect_object(uint32_t index, Ray& ray, Hit& hit) const {
    return intersect_object_with(index, ray, hit, [&](const Shape& shape, Ray& r) { return shape.intersect(r, hit); });
}

bool RenderScene::occluded_by_object(uint32_t index, const Ray& ray, DielectricShadows mode) const {
    const HotObject& o = objects_[index];
    if (o.dielectric && mode == DielectricShadows::None) return false;
    if (o.motion) return o.shape->occluded(o.motion->at(ray.time).inverse().ray(ray));
    return o.transformed ? o.shape->occluded(o.object_from_world.ray(ray)) : o.shape->occluded(ray);
}

template <bool AnyHit, class Visit, class Count>
bool RenderScene::visit_objects(Ray& ray, Visit&& visit, const Count& count) const {
    if (top_level_.nodes().empty() || few_objects_.empty()) return top_level_.traverse<AnyHit>(ray, visit, count);
    bool hit = false;
    const Vec3 inv_dir(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z);
    for (const auto& [box, object] : few_objects_) {
        float enter, exit;
        if (!box.intersect(ray.origin, inv_dir, ray.tmin, ray.tmax, enter, exit)) continue;
        count.node();  // an entered box counts as the visited node it stands for
        if (visit(object, ray)) {
            hit = true;
            if constexpr (AnyHit) return true;
        }
    }
    return hit;
}

bool RenderScene::intersect(Ray& ray, Hit& hit) const {
    return visit_objects<false>(ray, [&](uint32_t object, Ray& r) { return intersect_object(object, r, hit); });
}

bool RenderScene::occluded(const Ray& ray, DielectricShadows mode) const {
    Ray r = ray;
    return visit_objects<true>(r, [&](uint32_t object, Ray& rr) { return occluded_by_object(object, rr, mode); });
}

bool RenderScene::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
    auto counted = [&](const Shape& shape, Ray& r) { return shape.intersect_counted(r, hit, stats); };
    return visit_objects<false>(
        ray, [&](uint32_t object, Ray& r) { return intersect_object_with(object, r, hit, counted); },
        TraversalCount{&stats});
}

bool RenderScene::occluded_counted(const Ray& ray, DielectricShadows mode, TraversalStats& stats) const {
    Ray r = ray;
    auto occluded_by = [&](uint32_t index, Ray& rr) {
        const HotObject& o = objects_[index];
        if (o.dielectric && mode == DielectricShadows::None) return false;
        if (o.motion) return o.shape->occluded_counted(o.motion->at(rr.time).inverse().ray(rr), stats);
        return o.shape->occluded_counted(o.transformed ? o.object_from_world.ray(rr) : rr, stats);
    };
    return visit_objects<true>(r, occluded_by, TraversalCount{&stats});
}

SurfaceInteraction RenderScene::interaction(const Ray& ray, const Hit& hit) const {
    const HotObject& hot = objects_[hit.object];
    const SceneObject& o = scene_.objects()[hit.object];
    SurfaceInteraction si;
    if (!hot.transformed) {
        o.shape->interaction(ray, hit, si, detail_);
    } else {
        Transform moved;
        if (hot.motion) moved = hot.motion->at(ray.time);
        const Transform& world_from_object = hot.motion ? moved : o.world_from_object;
        o.shape->interaction(world_from_object.inverse().ray(ray), hit, si, detail_);
        si.p = world_from_object.point(si.p);
        si.geometric_normal = normalize(world_from_object.normal(si.geometric_normal));
        si.shading_normal = normalize(world_from_object.normal(si.shading_normal));
        si.front_face = dot(ray.direction, si.geometric_normal) < 0.0f;
        if (detail_ == InteractionDetail::Full) {
            // The derivatives are tangent vectors; the curvature scales as 1/length, here by
            // the square root of the area scale of the tangent plane (exact for a uniform scale).
            const float object_area = length(cross(si.dpdu, si.dpdv));
            si.dpdu = world_from_object.vector(si.dpdu);
            si.dpdv = world_from_object.vector(si.dpdv);
            si.tangent = world_from_object.vector(si.tangent);
            // A mirroring placement turns n × t the other way round.
            if (world_from_object.swaps_handedness()) si.tangent_sign = -si.tangent_sign;
            const float world_area = length(cross(si.dpdu, si.dpdv));
            if (object_area > 0.0f && world_area > 0.0f) si.curvature *= std::sqrt(object_area / world_area);
        }
    }
    si.time = ray.time;
    if (!si.blends_materials) si.materials[0] = o.material;
    return si;
}

SceneStatistics RenderScene::statistics() const {
    SceneStatistics s;
    const std::vector<SceneObject>& objects = scene_.objects();
    s.objects = objects.size();
    std::unordered_set<const Shape*> seen;
    for (const SceneObject& o : objects) {
        s.instanced_triangles += o.shape->triangle_count();
        if (seen.insert(o.shape.get()).second) {
            ++s.unique_shapes;
            s.unique_triangles += o.shape->triangle_count();
            s.memory_bytes += o.shape->memory_bytes();
        }
    }
    s.memory_bytes += top_level_.memory_bytes() + objects_.size() * sizeof(HotObject);
    return s;
}

}  // namespace glint
