#include "glint/math/quaternion.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

Quaternion normalized(const Quaternion& q) {
    const double n = std::sqrt(dot(q, q));
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

}  // namespace

Quaternion Quaternion::from_rotation(const std::array<std::array<double, 3>, 3>& r) {
    // Shoemake's branch on the largest of w², x², y², z², which keeps the division stable.
    const double trace = r[0][0] + r[1][1] + r[2][2];
    Quaternion q;
    if (trace > 0.0) {
        const double s = 2.0 * std::sqrt(trace + 1.0);
        q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
    } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]);
        q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
    } else if (r[1][1] > r[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]);
        q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]);
        q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
    }
    return normalized(q);
}

std::array<std::array<double, 3>, 3> Quaternion::to_rotation() const {
    const double xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z;
    const double wx = w * x, wy = w * y, wz = w * z;
    return {{{1.0 - 2.0 * (yy + zz), 2.0 * (xy - wz), 2.0 * (xz + wy)},
             {2.0 * (xy + wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz - wx)},
             {2.0 * (xz - wy), 2.0 * (yz + wx), 1.0 - 2.0 * (xx + yy)}}};
}

double dot(const Quaternion& a, const Quaternion& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }

double angle_between(const Quaternion& a, const Quaternion& b) {
    return 2.0 * std::acos(std::clamp(std::abs(dot(a, b)), 0.0, 1.0));
}

Quaternion slerp(const Quaternion& a, const Quaternion& b, double s) { return SlerpArc(a, b).at(s); }

SlerpArc::SlerpArc(const Quaternion& a, const Quaternion& b) : a_(a), b_(b) {
    double c = dot(a, b);
    if (c < 0.0) {
        b_ = {-b.w, -b.x, -b.y, -b.z};
        c = -c;
    }
    // Nearly equal rotations: sin θ → 0, and the linear blend is the limit.
    if (c < 0.9995) {
        theta_ = std::acos(c);
        cot_theta_ = c / std::sin(theta_);
        inv_sin_theta_ = 1.0 / std::sin(theta_);
    }
}

Quaternion SlerpArc::at(double s) const {
    if (theta_ == 0.0) {
        return normalized({(1.0 - s) * a_.w + s * b_.w, (1.0 - s) * a_.x + s * b_.x, (1.0 - s) * a_.y + s * b_.y,
                           (1.0 - s) * a_.z + s * b_.z});
    }
    // Shoemake's weights sin((1 − s)θ)/sin θ and sin(sθ)/sin θ; the first by the angle
    // difference identity, sin((1 − s)θ) = sin θ cos(sθ) − cos θ sin(sθ), so that one sincos
    // gives both. The blend of two unit quaternions by these weights is a unit quaternion.
    const double sin_s_theta = std::sin(s * theta_), cos_s_theta = std::cos(s * theta_);
    const double wa = cos_s_theta - cot_theta_ * sin_s_theta, wb = sin_s_theta * inv_sin_theta_;
    return {wa * a_.w + wb * b_.w, wa * a_.x + wb * b_.x, wa * a_.y + wb * b_.y, wa * a_.z + wb * b_.z};
}

}  // namespace glint
