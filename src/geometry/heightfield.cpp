#include "glint/geometry/heightfield.h"

#include "glint/geometry/triangle_differentials.h"

#include "glint/geometry/triangle.h"
#include "glint/math/constants.h"
#include "glint/scene_format/param_table.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace glint {

Heightfield::Heightfield(uint32_t nx, uint32_t nz, std::vector<float> heights, Vec2 min_xz, Vec2 max_xz)
    : nx_(nx), nz_(nz), heights_(std::move(heights)), min_(min_xz), max_(max_xz) {
    if (nx < 2 || nz < 2) throw std::invalid_argument("heightfield needs at least 2×2 vertices");
    if (heights_.size() != size_t(nx) * nz)
        throw std::invalid_argument("heightfield has " + std::to_string(heights_.size()) + " heights for a " +
                                    std::to_string(nx) + "×" + std::to_string(nz) + " grid");
    if (!(max_.x > min_.x && max_.y > min_.y)) throw std::invalid_argument("heightfield extent is empty");
    cell_size_ = Vec2((max_.x - min_.x) / float(nx - 1), (max_.y - min_.y) / float(nz - 1));
    float lo = kInfinity, hi = -kInfinity;
    for (float h : heights_) {
        if (!std::isfinite(h)) throw std::invalid_argument("heightfield has a non-finite height");
        lo = std::min(lo, h);
        hi = std::max(hi, h);
    }
    bounds_ = Bounds3(Vec3(min_.x, lo, min_.y), Vec3(max_.x, hi, max_.y));
}

Vec3 Heightfield::vertex(uint32_t i, uint32_t j) const {
    return {min_.x + float(i) * cell_size_.x, height(i, j), min_.y + float(j) * cell_size_.y};
}

Vec3 Heightfield::vertex_normal(uint32_t i, uint32_t j) const {
    // Central differences (one-sided at the border) of y(x, z); n ∝ (-∂y/∂x, 1, -∂y/∂z).
    const uint32_t i0 = i > 0 ? i - 1 : i, i1 = i + 1 < nx_ ? i + 1 : i;
    const uint32_t j0 = j > 0 ? j - 1 : j, j1 = j + 1 < nz_ ? j + 1 : j;
    const float dydx = (height(i1, j) - height(i0, j)) / (float(i1 - i0) * cell_size_.x);
    const float dydz = (height(i, j1) - height(i, j0)) / (float(j1 - j0) * cell_size_.y);
    return normalize(Vec3(-dydx, 1.0f, -dydz));
}

bool Heightfield::intersect_cell(uint32_t i, uint32_t j, const WatertightRay& shear, Ray& ray, Hit& hit) const {
    // Cell (i, j) is split along its diagonal into (00, 01, 11) and (00, 11, 10), both
    // counter-clockwise seen from +y so that normals face up.
    const Vec3 v00 = vertex(i, j), v10 = vertex(i + 1, j), v01 = vertex(i, j + 1), v11 = vertex(i + 1, j + 1);
    const uint32_t cell = j * (nx_ - 1) + i;
    bool found = false;
    TriangleHit th;
    if (intersect_triangle_watertight(ray, shear, v00, v01, v11, th)) {
        ray.tmax = th.t;
        hit = Hit{th.t, hit.object, 2 * cell, th.v, th.w};
        found = true;
    }
    if (intersect_triangle_watertight(ray, shear, v00, v11, v10, th)) {
        ray.tmax = th.t;
        hit = Hit{th.t, hit.object, 2 * cell + 1, th.v, th.w};
        found = true;
    }
    return found;
}

bool Heightfield::traverse(Ray& ray, Hit& hit) const {
    const Vec3 inv_dir(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z);
    float t_enter, t_exit;
    if (!bounds_.intersect(ray.origin, inv_dir, ray.tmin, ray.tmax, t_enter, t_exit)) return false;
    const Vec3 start = ray.at(t_enter);
    const auto cell_index = [](float coord, float lo, float size, uint32_t cells) {
        const auto c = static_cast<int64_t>(std::floor((coord - lo) / size));
        return static_cast<int64_t>(std::clamp<int64_t>(c, 0, int64_t(cells) - 1));
    };
    const uint32_t cells_x = nx_ - 1, cells_z = nz_ - 1;
    // Meshes' watertight test (Woop et al. 2013): the two triangles of a cell and those of
    // its neighbours compute a shared edge's function identically, so no ray slips between.
    const WatertightRay shear(ray.direction);
    int64_t i = cell_index(start.x, min_.x, cell_size_.x, cells_x);
    int64_t j = cell_index(start.z, min_.y, cell_size_.y, cells_z);
    // 2D DDA in the xz plane: t of the next vertical grid line in x and in z.
    const int step_i = ray.direction.x > 0.0f ? 1 : -1;
    const int step_j = ray.direction.z > 0.0f ? 1 : -1;
    const float next_x = min_.x + float(i + (step_i > 0 ? 1 : 0)) * cell_size_.x;
    const float next_z = min_.y + float(j + (step_j > 0 ? 1 : 0)) * cell_size_.y;
    float t_max_x = ray.direction.x != 0.0f ? (next_x - ray.origin.x) * inv_dir.x : kInfinity;
    float t_max_z = ray.direction.z != 0.0f ? (next_z - ray.origin.z) * inv_dir.z : kInfinity;
    const float t_delta_x = ray.direction.x != 0.0f ? cell_size_.x * std::abs(inv_dir.x) : kInfinity;
    const float t_delta_z = ray.direction.z != 0.0f ? cell_size_.y * std::abs(inv_dir.z) : kInfinity;
    for (;;) {
        // Triangles of a cell lie inside its prism, so the first cell with a hit holds
        // the closest hit.
        if (intersect_cell(uint32_t(i), uint32_t(j), shear, ray, hit)) return true;
        const float t_next = std::min(t_max_x, t_max_z);
        if (t_next > t_exit || t_next > ray.tmax) return false;
        if (t_max_x < t_max_z) {
            i += step_i;
            t_max_x += t_delta_x;
            if (i < 0 || i >= int64_t(cells_x)) return false;
        } else {
            j += step_j;
            t_max_z += t_delta_z;
            if (j < 0 || j >= int64_t(cells_z)) return false;
        }
    }
}

bool Heightfield::intersect(Ray& ray, Hit& hit) const { return traverse(ray, hit); }

bool Heightfield::occluded(const Ray& ray) const {
    Ray r = ray;
    Hit scratch;
    return traverse(r, scratch);
}

void Heightfield::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si, InteractionDetail detail) const {
    const uint32_t cell = hit.primitive / 2;
    const uint32_t i = cell % (nx_ - 1), j = cell / (nx_ - 1);
    const bool second = hit.primitive % 2 == 1;
    const uint32_t ci[3][2] = {{i, j}, {second ? i + 1 : i, j + 1}, {i + 1, second ? j : j + 1}};
    const float b1 = hit.u, b2 = hit.v, b0 = 1.0f - b1 - b2;
    const Vec3 p0 = vertex(ci[0][0], ci[0][1]), p1 = vertex(ci[1][0], ci[1][1]), p2 = vertex(ci[2][0], ci[2][1]);
    si.p = p0 * b0 + p1 * b1 + p2 * b2;
    const Vec3 ng = normalize(cross(p1 - p0, p2 - p0));
    si.geometric_normal = ng;
    const Vec3 ns = vertex_normal(ci[0][0], ci[0][1]) * b0 + vertex_normal(ci[1][0], ci[1][1]) * b1 +
                    vertex_normal(ci[2][0], ci[2][1]) * b2;
    si.shading_normal = face_forward(normalize(ns), ng);
    si.front_face = dot(ray.direction, ng) < 0.0f;
    if (detail == InteractionDetail::WithoutTextureCoordinates) return;
    const Vec2 extent(max_.x - min_.x, max_.y - min_.y);
    auto uv_of = [&](const Vec3& p) { return Vec2((p.x - min_.x) / extent.x, (p.z - min_.y) / extent.y); };
    si.uv = uv_of(si.p);
    const TriangleDerivatives derivatives = triangle_derivatives(p0, p1, p2, uv_of(p0), uv_of(p1), uv_of(p2));
    si.dpdu = derivatives.dpdu;
    si.dpdv = derivatives.dpdv;
    si.curvature =
        triangle_curvature(p0, p1, p2, normalize(vertex_normal(ci[0][0], ci[0][1])),
                           normalize(vertex_normal(ci[1][0], ci[1][1])), normalize(vertex_normal(ci[2][0], ci[2][1])));
}

std::size_t Heightfield::memory_bytes() const { return sizeof(*this) + heights_.size() * sizeof(float); }

std::shared_ptr<Shape> Heightfield::from_params(const ParamTable& t, const BuildContext&) {
    const ParamValue& res = t.require("resolution", "[nx, nz], the number of grid vertices along x and z");
    const auto& r = res.as_array(t.name_of("resolution"));
    if (r.size() != 2) res.fail(t.name_of("resolution"), "[nx, nz], two integers");
    const int64_t nx = r[0].as_integer(t.name_of("resolution") + "[0]"),
                  nz = r[1].as_integer(t.name_of("resolution") + "[1]");
    constexpr int64_t kMaxVertices = int64_t(1) << 24;
    if (nx < 2 || nz < 2 || nx > kMaxVertices || nz > kMaxVertices || nx * nz > kMaxVertices)
        res.fail(t.name_of("resolution"), "at least 2×2 and at most 16M grid vertices");
    const Vec2 lo = t.require("min", "[x, z]").as_vec2(t.name_of("min"));
    const Vec2 hi = t.require("max", "[x, z]").as_vec2(t.name_of("max"));
    if (!(hi.x > lo.x && hi.y > lo.y)) t.fail("max", "a corner beyond min on both x and z");
    std::vector<float> heights(std::size_t(nx * nz), t.number("height", 0.0f));
    if (const ParamValue* h = t.find("heights")) {
        // Row by row along +z, x fastest; either flat or one array per row.
        std::vector<const ParamValue*> values;
        for (const ParamValue& e : h->as_array(t.name_of("heights"))) {
            if (!e.is_array()) {
                values.push_back(&e);
                continue;
            }
            const auto& row = e.as_array(t.name_of("heights"));
            if (int64_t(row.size()) != nx) e.fail(t.name_of("heights") + " row", fmt::format("nx = {} heights", nx));
            for (const ParamValue& x : row) values.push_back(&x);
        }
        if (values.size() != heights.size())
            h->fail(t.name_of("heights"), fmt::format("nx·nz = {} heights, row by row (x fastest)", heights.size()));
        for (std::size_t i = 0; i < values.size(); ++i) heights[i] += values[i]->as_float(fmt::format("{}[{}]", t.name_of("heights"), i));
    }
    for (const ParamTable* w : t.tables("waves")) {
        // A sum of sine waves keeps a water surface a few lines long (the handout's pool).
        const float amplitude = w->require_number("amplitude");
        const float wavelength = w->require_number("wavelength");
        if (!(wavelength > 0.0f)) w->fail("wavelength", "a positive wavelength in world units");
        const Vec2 dir = w->vec2("direction", Vec2(1.0f, 0.0f));
        const float len = std::sqrt(dir.x * dir.x + dir.y * dir.y);
        if (!(len > 0.0f)) w->fail("direction", "a non-zero direction [dx, dz]");
        const float phase = radians(w->number("phase", 0.0f));
        w->reject_unknown_keys();
        const float k = 2.0f * kPi / wavelength;
        for (int64_t j = 0; j < nz; ++j)
            for (int64_t i = 0; i < nx; ++i) {
                const float x = lo.x + (hi.x - lo.x) * float(i) / float(nx - 1);
                const float z = lo.y + (hi.y - lo.y) * float(j) / float(nz - 1);
                heights[std::size_t(j * nx + i)] += amplitude * std::sin(k * (dir.x * x + dir.y * z) / len + phase);
            }
    }
    return std::make_shared<Heightfield>(uint32_t(nx), uint32_t(nz), std::move(heights), lo, hi);
}


}  // namespace glint
