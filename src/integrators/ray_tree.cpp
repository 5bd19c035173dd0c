#include "glint/integrators/ray_tree.h"

namespace glint {

std::string_view ray_kind_name(RayKind kind) {
    switch (kind) {
        case RayKind::Camera:
            return "camera";
        case RayKind::Reflection:
            return "reflection";
        case RayKind::Refraction:
            return "refraction";
        case RayKind::Shadow:
            return "shadow";
        case RayKind::Bounce:
            return "bounce";
        case RayKind::GlossyReflection:
            return "glossy reflection";
        case RayKind::GlossyTransmission:
            return "glossy transmission";
    }
    return "ray";
}

Color RayTree::total_contribution() const {
    Color sum;
    for (const RayTreeNode& node : nodes_) sum += node.contribution;
    return sum;
}

int32_t RayTree::add_ray(RayKind kind, int32_t parent, uint32_t depth, const Ray& ray, const Color& weight) {
    RayTreeNode node;
    node.kind = kind;
    node.parent = parent;
    node.depth = depth;
    node.origin = ray.origin;
    node.direction = ray.direction;
    node.time = ray.time;
    node.weight = weight;
    nodes_.push_back(node);
    return static_cast<int32_t>(nodes_.size() - 1);
}

void RayTree::set_hit(int32_t node, float t, uint32_t object, uint32_t material, const Vec3& normal) {
    RayTreeNode& n = nodes_[std::size_t(node)];
    n.hit = true;
    n.t = t;
    n.object = object;
    n.material = material;
    n.normal = normal;
}

void RayTree::add_radiance(int32_t node, const Color& radiance) {
    RayTreeNode& n = nodes_[std::size_t(node)];
    n.contribution += n.weight * radiance;
}

void RayTree::add_shadow_ray(int32_t parent, const Ray& ray, uint32_t light, bool blocked, const Color& radiance) {
    const uint32_t depth = nodes_[std::size_t(parent)].depth;
    const Color weight = nodes_[std::size_t(parent)].weight;
    const int32_t node = add_ray(RayKind::Shadow, parent, depth, ray, weight);
    RayTreeNode& n = nodes_[std::size_t(node)];
    n.light = light;
    n.blocked = blocked;
    n.t = ray.tmax;  // the distance to the light (infinite for a directional one)
    if (!blocked) n.contribution = n.weight * radiance;
}

}  // namespace glint
