#include "glint/integrators/explanation_format.h"

#include "glint/lights/light.h"
#include "glint/scene/render_scene.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <vector>

namespace glint {

namespace {

std::string object_name(const RenderScene& scene, uint32_t object) {
    const std::string& name = scene.description().objects()[object].name;
    return name.empty() ? fmt::format("object #{}", object) : fmt::format("'{}'", name);
}

std::string material_name(const RenderScene& scene, uint32_t material) {
    const std::string& name = scene.material(material).name;
    return name.empty() ? fmt::format("material #{}", material) : fmt::format("'{}'", name);
}

std::string light_name(const RenderScene& scene, uint32_t light) {
    return fmt::format("light #{} ({})", light, scene.all_lights()[light]->type_name());
}

/// One number for a grey, three otherwise.
std::string rgb(const Color& c) {
    if (c.r == c.g && c.g == c.b) return fmt::format("{:.4g}", c.r);
    return fmt::format("{:.4g} {:.4g} {:.4g}", c.r, c.g, c.b);
}
std::string xyz(const Vec3& v) { return fmt::format("({:.3g}, {:.3g}, {:.3g})", v.x, v.y, v.z); }

/// What a ray's weight is multiplied by relative to its parent's: the Fresnel reflectance
/// or transmittance of a Whitted child, f·|cos|/pdf/N of one of N glossy samples, the BSDF
/// weight of a path bounce.
Color factor(const RayTree& tree, const RayTreeNode& node) {
    if (node.parent < 0) return node.weight;
    const Color& parent = tree.nodes()[std::size_t(node.parent)].weight;
    auto ratio = [](float child, float parent_weight) { return parent_weight != 0.0f ? child / parent_weight : 0.0f; };
    return {ratio(node.weight.r, parent.r), ratio(node.weight.g, parent.g), ratio(node.weight.b, parent.b)};
}

void print_ray(std::string& out, const RenderScene& scene, const RayTree& tree,
               const std::vector<std::vector<int32_t>>& children, int32_t index, int indent) {
    const RayTreeNode& node = tree.nodes()[std::size_t(index)];
    std::string line = fmt::format("{:{}}#{} {} ray", "", indent * 2, index, ray_kind_name(node.kind));
    if (node.kind == RayKind::Shadow) {
        line += fmt::format(" to {}: {}", light_name(scene, node.light), node.blocked ? "blocked" : "reaches it");
    } else {
        if (node.kind != RayKind::Camera) line += fmt::format(" (factor {})", rgb(factor(tree, node)));
        if (node.hit)
            line += fmt::format(": hits {} ({}) at t = {:.4g}, normal {}", object_name(scene, node.object),
                                material_name(scene, node.material), node.t, xyz(node.normal));
        else
            line += ": misses everything, sees the background";
    }
    line += fmt::format("; weight {}; adds {}", rgb(node.weight), rgb(node.contribution));
    out += line + "\n";
    for (const int32_t child : children[std::size_t(index)]) print_ray(out, scene, tree, children, child, indent + 1);
}

}  // namespace

std::string explanation_text(const RenderScene& scene, const RenderSettings& s, const PixelExplanation& e) {
    const uint32_t spp = s.samples_per_axis * s.samples_per_axis;
    std::string out = fmt::format("pixel ({}, {}) of {}×{}, {} spp, {} integrator, seed {}\n", e.x, e.y, s.width,
                                  s.height, spp, s.integrator, s.seed);
    out += fmt::format("value {}  (Σ filter weight × radiance / Σ filter weight: what `glint render` writes there)\n",
                       rgb(e.value));
    for (const ExplainedSample& sample : e.samples) {
        out += fmt::format("\nsample {} at film ({:.3f}, {:.3f}), filter weight {:.4g}, radiance {}\n", sample.index,
                           sample.film_position.x, sample.film_position.y, sample.filter_weight, rgb(sample.radiance));
        if (!sample.tree) continue;
        const RayTree& tree = *sample.tree;
        std::vector<std::vector<int32_t>> children(tree.nodes().size());
        for (std::size_t i = 0; i < tree.nodes().size(); ++i)
            if (tree.nodes()[i].parent >= 0) children[std::size_t(tree.nodes()[i].parent)].push_back(int32_t(i));
        for (std::size_t i = 0; i < tree.nodes().size(); ++i)
            if (tree.nodes()[i].parent < 0) print_ray(out, scene, tree, children, int32_t(i), 1);
        out += fmt::format(
            "  the rays add up to {} (weight: throughput from the camera; adds: weight × the light the ray "
            "brings by itself)\n",
            rgb(tree.total_contribution()));
    }
    return out;
}

namespace {

nlohmann::json to_json(const Color& c) { return {c.r, c.g, c.b}; }
nlohmann::json to_json(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json ray_json(const RenderScene& scene, const RayTree& tree, std::size_t index) {
    const RayTreeNode& node = tree.nodes()[index];
    nlohmann::json ray = {{"id", index},
                          {"kind", ray_kind_name(node.kind)},
                          {"parent", node.parent < 0 ? nlohmann::json(nullptr) : nlohmann::json(node.parent)},
                          {"depth", node.depth},
                          {"origin", to_json(node.origin)},
                          {"direction", to_json(node.direction)},
                          {"weight", to_json(node.weight)},
                          {"factor", to_json(factor(tree, node))},
                          {"contribution", to_json(node.contribution)}};
    if (node.kind == RayKind::Shadow) {
        ray["light"] = {{"index", node.light}, {"type", scene.all_lights()[node.light]->type_name()}};
        ray["blocked"] = node.blocked;
    } else if (node.hit) {
        ray["hit"] = {{"t", node.t},
                      {"object", node.object},
                      {"object_name", scene.description().objects()[node.object].name},
                      {"material", node.material},
                      {"material_name", scene.material(node.material).name},
                      {"normal", to_json(node.normal)}};
    } else {
        ray["hit"] = nullptr;
    }
    return ray;
}

}  // namespace

std::string explanation_json(const RenderScene& scene, const RenderSettings& s, const PixelExplanation& e) {
    nlohmann::json samples = nlohmann::json::array();
    for (const ExplainedSample& sample : e.samples) {
        nlohmann::json j = {{"index", sample.index},
                            {"film_position", {sample.film_position.x, sample.film_position.y}},
                            {"filter_weight", sample.filter_weight},
                            {"radiance", to_json(sample.radiance)}};
        if (sample.tree) {
            nlohmann::json rays = nlohmann::json::array();
            for (std::size_t i = 0; i < sample.tree->nodes().size(); ++i)
                rays.push_back(ray_json(scene, *sample.tree, i));
            j["rays"] = std::move(rays);
        }
        samples.push_back(std::move(j));
    }
    const nlohmann::json out = {{"pixel", {e.x, e.y}},
                                {"image", {s.width, s.height}},
                                {"spp", s.samples_per_axis * s.samples_per_axis},
                                {"integrator", s.integrator},
                                {"seed", s.seed},
                                {"value", to_json(e.value)},
                                {"samples", std::move(samples)}};
    return out.dump(2);
}

}  // namespace glint
