#pragma once
/// \file glTF 2.0 node animation (§3.11 "Animations"): channels that drive a node's
/// translation, rotation or scale through samplers, evaluated at any time as Appendix C
/// ("Animation Sampler Interpolation Modes") says. Internal: the scene loader poses the
/// nodes with it over the camera's shutter (gltf_motion.h).

#include "gltf_document.h"
#include "import_notes.h"

#include "glint/math/quaternion.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace glint::gltf {

/// Every node's local transform at one time.
struct NodePose {
    /// Per node: T·R·S of its (animated) translation, rotation and scale, or its matrix.
    std::vector<Matrix4> local;
    /// Per node: its (animated) rotation; the identity for a node given by a matrix.
    std::vector<Quaternion> rotation;
};

class NodeAnimation {
public:
    /// Read the `animations` of `doc`. Channels the loader does not map (morph target
    /// `weights`, paths of extensions, no target node) are noted in `notes` as ignored.
    /// Throws SceneError naming the file and the JSON path of the first problem, e.g.
    /// "scene.gltf: animations[0].samplers[1].input: ...": a missing or mistyped accessor,
    /// key times that do not increase, an output count that does not match the input's.
    NodeAnimation(const Document& doc, ImportNotes& notes);

    /// Entries of the file's `animations` array; all of them play at once from time 0.
    [[nodiscard]] std::size_t animation_count() const { return animations_; }
    /// True if a channel drives some node's translation, rotation or scale.
    [[nodiscard]] bool moves_nodes() const { return !channels_.empty(); }
    /// The key times of every channel, increasing, without repeats; with `step_only`, of
    /// STEP channels only (where values jump).
    [[nodiscard]] std::vector<float> key_times(bool step_only = false) const;
    /// The nodes at `time` (seconds): each channel's value replaces its node's property
    /// (§3.11), held before the first key and after the last.
    [[nodiscard]] NodePose pose(float time) const;

private:
    enum class Interpolation { Linear, Step, CubicSpline };
    enum class Path { Translation, Rotation, Scale };
    /// One sampler as a channel reads it: `values` holds `components` floats per element,
    /// and a cubic spline three elements per key (in-tangent, value, out-tangent).
    struct Curve {
        Interpolation interpolation = Interpolation::Linear;
        std::vector<float> times;
        std::vector<float> values;
        std::size_t components = 3;
    };
    struct Channel {
        std::size_t node = 0;
        Path path = Path::Translation;
        Curve curve;
    };
    /// The node properties a channel may replace, as the file gives them.
    struct Rest {
        Vec3 translation{0.0f}, scale{1.0f};
        float rotation[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // x, y, z, w
        Matrix4 matrix;
    };

    /// The sampler `sampler`, at JSON path `where`, as a channel of `path` reads it.
    [[nodiscard]] static Curve read_curve(const Document& doc, const nlohmann::json& sampler, const std::string& where,
                                          Path path);
    /// The value of `curve` at `time` (Appendix C); rotations come out unit length.
    [[nodiscard]] static std::array<double, 4> evaluate(const Curve& curve, bool rotation, float time);

    std::size_t animations_ = 0;
    std::vector<Channel> channels_;
    std::vector<Rest> rest_;
    std::vector<bool> animated_;
};

}  // namespace glint::gltf
