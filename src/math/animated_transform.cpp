#include "glint/math/animated_transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace glint {

namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

double determinant(const Matrix3& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/// (A⁻¹)ᵀ by cofactors: cof(A) / det(A).
Matrix3 inverse_transpose(const Matrix3& a) {
    const double d = determinant(a);
    Matrix3 c;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / d;
        }
    return c;
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
    Matrix3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

/// Largest |S·c| over the corners c of `b`: no point of the box is farther from the origin
/// once stretched (the norm is convex).
double stretched_radius(const Matrix3& s, const Bounds3& b) {
    double r = 0.0;
    for (int i = 0; i < 8; ++i) {
        const double c[3] = {(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z};
        double len2 = 0.0;
        for (int row = 0; row < 3; ++row) {
            const double v = s[row][0] * c[0] + s[row][1] * c[1] + s[row][2] * c[2];
            len2 += v * v;
        }
        r = std::max(r, std::sqrt(len2));
    }
    return r;
}

}  // namespace

AnimatedTransform::AnimatedTransform(std::vector<MotionKey> keys) : keys_(std::move(keys)) {
    if (keys_.size() < 2) throw std::invalid_argument("motion needs at least two keys");
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        if (!std::isfinite(keys_[i].time))
            throw std::invalid_argument("motion key " + std::to_string(i + 1) + " has a time that is not finite");
        if (i > 0 && !(keys_[i].time > keys_[i - 1].time))
            throw std::invalid_argument("motion key " + std::to_string(i + 1) + " at time " +
                                        std::to_string(keys_[i].time) + " is not after the key before it, at time " +
                                        std::to_string(keys_[i - 1].time) + " (keys in increasing time)");
        const auto& m = keys_[i].transform.matrix().m;
        if (m[3][0] != 0.0f || m[3][1] != 0.0f || m[3][2] != 0.0f || m[3][3] != 1.0f)
            throw std::invalid_argument("motion key " + std::to_string(i + 1) + " is a projective transform");
        parts_.push_back(decompose(keys_[i].transform));
    }
    for (std::size_t i = 0; i + 1 < keys_.size(); ++i)
        intervals_.push_back(
            {SlerpArc(parts_[i].rotation, parts_[i + 1].rotation), keys_[i].transform == keys_[i + 1].transform});
}

AnimatedTransform::Parts AnimatedTransform::decompose(const Transform& t) {
    const auto& m = t.matrix().m;
    Parts p;
    Matrix3 linear;
    for (int i = 0; i < 3; ++i) {
        p.translation[std::size_t(i)] = m[i][3];
        for (int j = 0; j < 3; ++j) linear[i][j] = m[i][j];
    }
    // Polar decomposition M = R·S by Higham's iteration R ← (R + R⁻ᵀ)/2, which converges
    // quadratically to the nearest orthogonal matrix. A mirroring M gives det R = −1; then
    // (−R)·(−S) = M with −R a rotation, so the quaternion stays defined.
    Matrix3 r = linear;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const Matrix3 it = inverse_transpose(r);
        double change = 0.0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const double next = 0.5 * (r[i][j] + it[i][j]);
                change = std::max(change, std::abs(next - r[i][j]));
                r[i][j] = next;
            }
        if (change < 1e-14) break;
    }
    if (determinant(r) < 0.0)
        for (auto& row : r)
            for (double& v : row) v = -v;
    Matrix3 rt;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rt[i][j] = r[j][i];
    p.rotation = Quaternion::from_rotation(r);
    p.stretch = multiply(rt, linear);
    return p;
}

Transform AnimatedTransform::interpolate(std::size_t i, double s) const {
    const Parts& a = parts_[i];
    const Parts& b = parts_[i + 1];
    Matrix3 stretch;
    auto blend_stretch = [&] {
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col)
                stretch[row][col] = (1.0 - s) * a.stretch[row][col] + s * b.stretch[row][col];
    };
    blend_stretch();
    // M = T·R·S, so M⁻¹ = S⁻¹·Rᵀ·T⁻¹. Keys of one handedness have stretches of one sign of
    // definiteness, and so has their blend: S is invertible. Between a mirrored key and one
    // that is not, the object flattens at one instant (det S = 0), where it has no area to
    // be hit; a time a step before stands in for it. (s > 0: key i itself is invertible.)
    while (determinant(stretch) == 0.0) {
        s = std::nextafter(s, 0.0);
        blend_stretch();
    }
    const Matrix3 rotation = intervals_[i].rotation.at(s).to_rotation();
    const Matrix3 linear = multiply(rotation, stretch);
    const Matrix3 stretch_inverse_t = inverse_transpose(stretch);
    Matrix3 inverse_linear{};  // S⁻¹·Rᵀ
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            for (int k = 0; k < 3; ++k) inverse_linear[row][col] += stretch_inverse_t[k][row] * rotation[col][k];
    double translation[3];
    for (int row = 0; row < 3; ++row)
        translation[row] = (1.0 - s) * a.translation[std::size_t(row)] + s * b.translation[std::size_t(row)];
    Matrix4 m = Matrix4::identity(), inverse = Matrix4::identity();
    for (int row = 0; row < 3; ++row) {
        m.m[row][3] = float(translation[row]);
        double inverse_translation = 0.0;
        for (int col = 0; col < 3; ++col) {
            m.m[row][col] = float(linear[row][col]);
            inverse.m[row][col] = float(inverse_linear[row][col]);
            inverse_translation -= inverse_linear[row][col] * translation[col];
        }
        inverse.m[row][3] = float(inverse_translation);
    }
    return Transform(m, inverse);
}

Transform AnimatedTransform::at(float time) const {
    if (!(time > keys_.front().time)) return keys_.front().transform;
    if (!(time < keys_.back().time)) return keys_.back().transform;
    const auto next =
        std::upper_bound(keys_.begin(), keys_.end(), time, [](float t, const MotionKey& key) { return t < key.time; });
    const std::size_t i = std::size_t(next - keys_.begin()) - 1;
    if (time == keys_[i].time) return keys_[i].transform;
    if (intervals_[i].still) return keys_[i].transform;
    return interpolate(i, (double(time) - keys_[i].time) / (double(keys_[i + 1].time) - keys_[i].time));
}

void AnimatedTransform::extend_over_interval(std::size_t i, const Bounds3& object_bounds, float t0, float t1,
                                             Bounds3& out) const {
    const double k0 = keys_[i].time, k1 = keys_[i + 1].time;
    const double s0 = std::clamp((double(t0) - k0) / (k1 - k0), 0.0, 1.0);
    const double s1 = std::clamp((double(t1) - k0) / (k1 - k0), 0.0, 1.0);
    if (!(s1 > s0)) return;  // an instant: bounds() added it
    // Sample the motion; between two samples a point p(t) = T(t) + R(t)·S(t)·x stays within
    // 2·δ·|S(t)·x| of the chord joining its sampled positions, δ being the angle turned in
    // one step (compare it with T(t) + R(tᵢ)·S(t)·x, which is affine in t). The union box of
    // the samples holds every chord, so padding it by 2·δ·r bounds the motion; without
    // rotation the samples alone are exact.
    const double angle = angle_between(parts_[i].rotation, parts_[i + 1].rotation) * (s1 - s0);
    constexpr double kStepAngle = 0.5 * 3.14159265358979 / 180.0;
    const int steps = std::clamp(int(std::ceil(angle / kStepAngle)), 1, 4096);
    Bounds3 swept;
    for (int k = 0; k <= steps; ++k) {
        const double s = s0 + (s1 - s0) * double(k) / double(steps);
        swept.extend(s == 0.0   ? keys_[i].transform.bounds(object_bounds)
                     : s == 1.0 ? keys_[i + 1].transform.bounds(object_bounds)
                                : interpolate(i, s).bounds(object_bounds));
    }
    if (angle > 0.0) {
        const double r = std::max(stretched_radius(parts_[i].stretch, object_bounds),
                                  stretched_radius(parts_[i + 1].stretch, object_bounds));
        const float pad = float(2.0 * (angle / steps) * r * 1.0001);
        swept = Bounds3(swept.lo - Vec3(pad), swept.hi + Vec3(pad));
    }
    out.extend(swept);
}

Bounds3 AnimatedTransform::bounds(const Bounds3& object_bounds, float t0, float t1) const {
    Bounds3 out;
    if (object_bounds.empty()) return out;
    // The ends (held before the first key and after the last), then each interval between.
    out.extend(at(t0).bounds(object_bounds));
    out.extend(at(t1).bounds(object_bounds));
    for (std::size_t i = 0; i + 1 < keys_.size(); ++i)
        if (t1 >= keys_[i].time && t0 <= keys_[i + 1].time) extend_over_interval(i, object_bounds, t0, t1, out);
    return out;
}

}  // namespace glint
