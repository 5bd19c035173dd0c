#pragma once
/// \file A transform that changes over time: keys at increasing times, interpolated as
/// translation and stretch lerped, rotation slerped (Shoemake and Duff, "Matrix Animation
/// and Polar Decomposition", 1992; pbrt-v4's AnimatedTransform). Motion blur's moving
/// objects; docs/scene-format.md defines scene time.

#include "glint/math/bounds3.h"
#include "glint/math/quaternion.h"
#include "glint/math/transform.h"

#include <array>
#include <vector>

namespace glint {

/// The transform in force at `time`.
struct MotionKey {
    float time = 0.0f;
    Transform transform;
};

class AnimatedTransform {
public:
    /// At least two keys with finite, strictly increasing times and affine transforms.
    /// Throws std::invalid_argument otherwise, naming the first key out of order.
    explicit AnimatedTransform(std::vector<MotionKey> keys);

    /// The transform at `time`: a key's own at its time, held before the first key and after
    /// the last, interpolated between.
    [[nodiscard]] Transform at(float time) const;
    /// A box around `object_bounds` carried by this transform at every time in [t0, t1].
    [[nodiscard]] Bounds3 bounds(const Bounds3& object_bounds, float t0, float t1) const;
    [[nodiscard]] const std::vector<MotionKey>& keys() const { return keys_; }

private:
    /// M = T·R·S: translation, rotation and the symmetric stretch of the polar decomposition.
    struct Parts {
        std::array<double, 3> translation{};
        Quaternion rotation;
        std::array<std::array<double, 3>, 3> stretch{};
    };
    /// From key i to key i + 1: the rotation's arc, and whether the two keys are equal.
    struct Interval {
        SlerpArc rotation;
        bool still = false;
    };
    [[nodiscard]] static Parts decompose(const Transform& t);
    /// Between keys i and i + 1, at s in [0, 1]; the inverse from the parts, not by
    /// inverting the matrix (a ray meets this once per moving object it passes).
    [[nodiscard]] Transform interpolate(std::size_t i, double s) const;
    /// Bounds of [t0, t1] ∩ [key i, key i + 1].
    void extend_over_interval(std::size_t i, const Bounds3& object_bounds, float t0, float t1, Bounds3& out) const;

    std::vector<MotionKey> keys_;
    std::vector<Parts> parts_;
    std::vector<Interval> intervals_;
};

}  // namespace glint
