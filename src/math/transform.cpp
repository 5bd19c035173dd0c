#include "glint/math/transform.h"

#include "glint/math/constants.h"

#include <cmath>
#include <stdexcept>

namespace glint {

Matrix4 Matrix4::identity() {
    Matrix4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0f;
    return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += double(m[i][k]) * double(o.m[k][j]);
            r.m[i][j] = static_cast<float>(s);
        }
    return r;
}

Matrix4 Matrix4::transposed() const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

bool Matrix4::inverse(Matrix4& out) const {
    // Gauss-Jordan elimination with partial pivoting, in double precision.
    double a[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a[i][j] = m[i][j];
            a[i][j + 4] = (i == j) ? 1.0 : 0.0;
        }
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        if (std::abs(a[pivot][col]) < 1e-300) return false;
        if (pivot != col)
            for (int j = 0; j < 8; ++j) std::swap(a[col][j], a[pivot][j]);
        const double inv_p = 1.0 / a[col][col];
        for (int j = 0; j < 8; ++j) a[col][j] *= inv_p;
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            const double f = a[r][col];
            if (f == 0.0) continue;
            for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
        }
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out.m[i][j] = static_cast<float>(a[i][j + 4]);
    return true;
}

Transform::Transform() : m_(Matrix4::identity()), inv_(Matrix4::identity()) {}

Transform::Transform(const Matrix4& m) : m_(m) {
    if (!m.inverse(inv_)) throw std::invalid_argument("transform matrix is singular (not invertible)");
}

Transform Transform::translate(const Vec3& t) {
    Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
    for (int i = 0; i < 3; ++i) {
        m.m[i][3] = t[i];
        inv.m[i][3] = -t[i];
    }
    return {m, inv};
}

Transform Transform::scale(const Vec3& s) {
    if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) throw std::invalid_argument("scale factor of zero");
    Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
    for (int i = 0; i < 3; ++i) {
        m.m[i][i] = s[i];
        inv.m[i][i] = 1.0f / s[i];
    }
    return {m, inv};
}

Transform Transform::rotate(float deg, const Vec3& axis_in) {
    // Rodrigues' rotation formula as a matrix.
    const Vec3 a = normalize(axis_in);
    const double th = double(deg) * std::numbers::pi / 180.0;
    const double s = std::sin(th), c = std::cos(th), t = 1.0 - c;
    Matrix4 m = Matrix4::identity();
    m.m[0][0] = float(a.x * a.x * t + c);
    m.m[0][1] = float(a.x * a.y * t - a.z * s);
    m.m[0][2] = float(a.x * a.z * t + a.y * s);
    m.m[1][0] = float(a.x * a.y * t + a.z * s);
    m.m[1][1] = float(a.y * a.y * t + c);
    m.m[1][2] = float(a.y * a.z * t - a.x * s);
    m.m[2][0] = float(a.x * a.z * t - a.y * s);
    m.m[2][1] = float(a.y * a.z * t + a.x * s);
    m.m[2][2] = float(a.z * a.z * t + c);
    return {m, m.transposed()};
}

Transform Transform::operator*(const Transform& o) const { return {m_ * o.m_, o.inv_ * inv_}; }

bool Transform::is_identity() const { return m_ == Matrix4::identity(); }

Vec3 Transform::point(const Vec3& p) const {
    const auto& a = m_.m;
    const float x = a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3];
    const float y = a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3];
    const float z = a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3];
    const float w = a[3][0] * p.x + a[3][1] * p.y + a[3][2] * p.z + a[3][3];
    return w == 1.0f ? Vec3(x, y, z) : Vec3(x, y, z) / w;
}

Vec3 Transform::vector(const Vec3& v) const {
    const auto& a = m_.m;
    return {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z, a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
            a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z};
}

Vec3 Transform::normal(const Vec3& n) const {
    const auto& a = inv_.m;  // (M^-1)^T · n
    return {a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z, a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z,
            a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z};
}

Ray Transform::ray(const Ray& r) const { return {point(r.origin), vector(r.direction), r.tmin, r.tmax, r.time}; }

Bounds3 Transform::bounds(const Bounds3& b) const {
    Bounds3 out;
    if (b.empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
        out.extend(point(corner));
    }
    return out;
}

bool Transform::swaps_handedness() const {
    const auto& a = m_.m;
    const float det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                      a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                      a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    return det < 0.0f;
}

}  // namespace glint
