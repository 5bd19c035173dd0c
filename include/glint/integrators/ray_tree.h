#pragma once
/// \file Why a pixel has its colour: the rays one of its samples cast, as a tree, with what
/// each ray met and what it added to the sample (glint explain; the viewer's inspector).
///
/// An integrator records into a RayTree only when TraceContext::tree is set, which the
/// render loop never does; the explanation then runs the very code the render runs. Each
/// node's `contribution` is what that ray adds to the sample's radiance by itself (a
/// background seen, an emission, ambient light, a shadow ray's light), already multiplied
/// by the throughput `weight` from the camera to it, so the contributions of all nodes sum
/// to the sample's radiance.

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace glint {

enum class RayKind : uint8_t {
    Camera,
    Reflection,          ///< Whitted's mirror reflection
    Refraction,          ///< Whitted's refraction
    Shadow,              ///< towards a light: blocked or not
    Bounce,              ///< the path integrator's next vertex, from sampling the BSDF
    GlossyReflection,    ///< Whitted's sample of a rough surface's glossy reflection
    GlossyTransmission,  ///< Whitted's sample of a rough dielectric's refraction
};

[[nodiscard]] std::string_view ray_kind_name(RayKind kind);

struct RayTreeNode {
    RayKind kind = RayKind::Camera;
    /// Index of the ray this one was cast from (−1 for the camera ray).
    int32_t parent = -1;
    /// Reflection/refraction depth (path length for the path integrator).
    uint32_t depth = 0;
    Vec3 origin, direction;
    /// The scene time the ray travelled at (motion blur).
    float time = 0.0f;
    /// Throughput from the camera to this ray: its radiance counts this much in the sample.
    Color weight{1.0f};
    /// What this ray adds to the sample by itself, weight included.
    Color contribution;

    /// Every kind but shadow rays: what they met (none: the background).
    bool hit = false;
    /// Where the ray ended: at its hit, or (shadow rays) at the light, infinite for a
    /// directional light.
    float t = 0.0f;
    uint32_t object = 0;
    uint32_t material = 0;
    /// Shading normal at the hit, on the side the ray came from.
    Vec3 normal;

    /// Shadow rays: the light (index into RenderScene::all_lights()) and whether it was blocked.
    uint32_t light = 0;
    bool blocked = false;
};

/// How a ray came about: what a recursive integrator hands down to record it.
struct RayBranch {
    RayKind kind = RayKind::Camera;
    int32_t parent = -1;
    /// Throughput from the camera to the ray.
    Color weight{1.0f};
};

/// The rays of one pixel sample, in the order they were cast (a parent before its children).
class RayTree {
public:
    [[nodiscard]] const std::vector<RayTreeNode>& nodes() const { return nodes_; }
    [[nodiscard]] Color total_contribution() const;

    /// A ray cast from `parent` (−1: the camera) with throughput `weight`; returns its index.
    int32_t add_ray(RayKind kind, int32_t parent, uint32_t depth, const Ray& ray, const Color& weight);
    /// What ray `node` met.
    void set_hit(int32_t node, float t, uint32_t object, uint32_t material, const Vec3& normal);
    /// The shading normal at ray `node`'s hit, once the integrator has it.
    void set_normal(int32_t node, const Vec3& normal) { nodes_[std::size_t(node)].normal = normal; }
    /// Ray `node` adds `radiance` (before its weight) to the sample.
    void add_radiance(int32_t node, const Color& radiance);
    /// A shadow ray from the hit of `parent` to light `light`: it adds `radiance` (before
    /// the parent's weight; ignored when blocked).
    void add_shadow_ray(int32_t parent, const Ray& ray, uint32_t light, bool blocked, const Color& radiance);

private:
    std::vector<RayTreeNode> nodes_;
};

/// One sample of a pixel as the render takes it.
struct CameraSample {
    /// Where on the film the sample's camera ray starts (pixel (x, y) covers [x, x+1)×[y, y+1)).
    Vec2 film_position;
    float filter_weight = 0.0f;
    Color radiance;
};

/// A sample as explain() reports it.
struct ExplainedSample : CameraSample {
    uint32_t index = 0;
    /// Recorded for the samples asked for.
    std::optional<RayTree> tree;
};

/// A pixel's samples and its value, Σ w·L / Σ w: the value `glint render` writes there with
/// the same scene and settings.
struct PixelExplanation {
    uint32_t x = 0, y = 0;
    std::vector<ExplainedSample> samples;
    Color value;
};

}  // namespace glint
