#include "glint/geometry/triangle_mesh.h"

#include "glint/geometry/triangle_differentials.h"

#include "glint/geometry/triangle.h"
#include "glint/sampling/warp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace glint {

namespace {

std::string mesh_label(const std::string& name) { return name.empty() ? "mesh" : "mesh '" + name + "'"; }

}  // namespace

TriangleMesh::TriangleMesh(MeshData data, std::string name) : data_(std::move(data)), name_(std::move(name)) {
    const std::string label = mesh_label(name_);
    const size_t vertex_count = data_.positions.size();
    if (data_.indices.empty()) throw std::invalid_argument(label + " has no triangles");
    if (data_.indices.size() % 3 != 0)
        throw std::invalid_argument(label + ": index count " + std::to_string(data_.indices.size()) +
                                    " is not a multiple of 3");
    for (size_t i = 0; i < data_.indices.size(); ++i)
        if (data_.indices[i] >= vertex_count)
            throw std::invalid_argument(label + ": triangle " + std::to_string(i / 3) + " uses vertex " +
                                        std::to_string(data_.indices[i]) + " but there are only " +
                                        std::to_string(vertex_count) + " vertices");
    for (size_t i = 0; i < vertex_count; ++i)
        if (!is_finite(data_.positions[i]))
            throw std::invalid_argument(label + ": vertex " + std::to_string(i) + " has a non-finite position");
    auto check_size = [&](size_t size, const char* what) {
        if (size != 0 && size != vertex_count)
            throw std::invalid_argument(label + ": " + std::to_string(size) + " " + what + " for " +
                                        std::to_string(vertex_count) + " vertices");
    };
    check_size(data_.normals.size(), "normals");
    check_size(data_.uvs.size(), "texture coordinates");
    check_size(data_.colors.size(), "vertex colours");
    check_size(data_.vertex_materials.size(), "vertex materials");
    check_size(data_.tangents.size(), "tangents");
    for (auto& n : data_.normals) n = unit_or_zero(n);
    if (data_.tangents.empty()) data_.tangents = compute_tangents(data_);
    for (const Vec3& p : data_.positions) bounds_.extend(p);
}

void TriangleMesh::prepare() {
    if (!bvh_.empty()) return;
    bvh_.build(data_.positions, data_.indices);
}

void TriangleMesh::transform_vertices(const Transform& world_from_object) {
    // In parallel: for the 871k-triangle dragon this is start-up time. Checked in one pass
    // and written in a second, so that a throw leaves the mesh as it was.
    std::atomic<bool> out_of_range{false};
    const Bounds3 bounds = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, data_.positions.size(), 16384), Bounds3(),
        [&](const tbb::blocked_range<size_t>& range, Bounds3 box) {
            for (size_t i = range.begin(); i < range.end(); ++i) {
                const Vec3 p = world_from_object.point(data_.positions[i]);
                if (!is_finite(p)) out_of_range.store(true, std::memory_order_relaxed);
                box.extend(p);
            }
            return box;
        },
        [](Bounds3 a, const Bounds3& b) {
            a.extend(b);
            return a;
        });
    if (out_of_range.load())
        throw std::invalid_argument(mesh_label(name_) + ": placed beyond the range of float coordinates");
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, data_.positions.size(), 16384), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i < range.end(); ++i) {
                data_.positions[i] = world_from_object.point(data_.positions[i]);
                if (!data_.normals.empty()) data_.normals[i] = unit_or_zero(world_from_object.normal(data_.normals[i]));
                if (!data_.tangents.empty())
                    data_.tangents[i].direction = unit_or_zero(world_from_object.vector(data_.tangents[i].direction));
            }
        });
    bounds_ = bounds;
    bvh_ = TriangleBvh();
    triangle_areas_.reset();
}

std::shared_ptr<TriangleMesh> TriangleMesh::placed(const Transform& world_from_object) const {
    auto mesh = std::make_shared<TriangleMesh>(MeshData(data_), name_);
    mesh->set_alpha_mask(alpha_mask_, alpha_cutoff_);
    mesh->transform_vertices(world_from_object);
    return mesh;
}

bool TriangleMesh::passes_alpha(uint32_t triangle, float b1, float b2) const {
    const uint32_t* idx = &data_.indices[3 * size_t(triangle)];
    const Vec2 uv = data_.uvs[idx[0]] * (1.0f - b1 - b2) + data_.uvs[idx[1]] * b1 + data_.uvs[idx[2]] * b2;
    return alpha_mask_->alpha(uv) >= alpha_cutoff_;
}

bool TriangleMesh::intersect_triangle(uint32_t triangle, Ray& ray, Hit& hit) const {
    const uint32_t* idx = &data_.indices[3 * size_t(triangle)];
    TriangleHit th;
    if (!intersect_triangle_watertight(ray, WatertightRay(ray.direction), data_.positions[idx[0]],
                                       data_.positions[idx[1]], data_.positions[idx[2]], th))
        return false;
    if (has_alpha_mask() && !passes_alpha(triangle, th.v, th.w)) return false;
    ray.tmax = th.t;
    hit.t = th.t;
    hit.primitive = triangle;
    hit.u = th.v;
    hit.v = th.w;
    return true;
}

bool TriangleMesh::intersect(Ray& ray, Hit& hit) const {
    if (!has_alpha_mask()) return bvh_.intersect<false>(ray, hit);
    return bvh_.intersect<false>(ray, hit,
                                 [this](uint32_t tri, float b1, float b2) { return passes_alpha(tri, b1, b2); });
}

bool TriangleMesh::occluded(const Ray& ray) const {
    Ray r = ray;
    Hit scratch;
    if (!has_alpha_mask()) return bvh_.intersect<true>(r, scratch);
    return bvh_.intersect<true>(r, scratch,
                                [this](uint32_t tri, float b1, float b2) { return passes_alpha(tri, b1, b2); });
}

uint32_t TriangleMesh::intersect_packet(RayPacket& packet, PacketHits& hits) const {
    if (has_alpha_mask()) return Shape::intersect_packet(packet, hits);
    return bvh_.intersect_packet(packet, hits);
}

uint32_t TriangleMesh::occluded_packet(const RayPacket& packet) const {
    if (has_alpha_mask()) return Shape::occluded_packet(packet);
    return bvh_.occluded_packet(packet);
}

bool TriangleMesh::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
    const TraversalCount count{&stats};
    if (!has_alpha_mask()) return bvh_.intersect<false>(ray, hit, AcceptAllHits{}, count);
    return bvh_.intersect<false>(
        ray, hit, [this](uint32_t tri, float b1, float b2) { return passes_alpha(tri, b1, b2); }, count);
}

bool TriangleMesh::occluded_counted(const Ray& ray, TraversalStats& stats) const {
    const TraversalCount count{&stats};
    Ray r = ray;
    Hit scratch;
    if (!has_alpha_mask()) return bvh_.intersect<true>(r, scratch, AcceptAllHits{}, count);
    return bvh_.intersect<true>(
        r, scratch, [this](uint32_t tri, float b1, float b2) { return passes_alpha(tri, b1, b2); }, count);
}

void TriangleMesh::interaction(const Ray& ray, const Hit& hit, SurfaceInteraction& si, InteractionDetail detail) const {
    const uint32_t* idx = &data_.indices[3 * size_t(hit.primitive)];
    const float b1 = hit.u, b2 = hit.v, b0 = 1.0f - b1 - b2;
    const Vec3& p0 = data_.positions[idx[0]];
    const Vec3& p1 = data_.positions[idx[1]];
    const Vec3& p2 = data_.positions[idx[2]];
    si.p = p0 * b0 + p1 * b1 + p2 * b2;
    const Vec3 ng = normalize(cross(p1 - p0, p2 - p0));
    si.geometric_normal = ng;
    si.front_face = dot(ray.direction, ng) < 0.0f;
    Vec3 ns = ng;
    if (!data_.normals.empty()) {
        const Vec3 interpolated = data_.normals[idx[0]] * b0 + data_.normals[idx[1]] * b1 + data_.normals[idx[2]] * b2;
        const float len = length(interpolated);
        if (len > 0.0f) ns = face_forward(interpolated / len, ng);
    }
    si.shading_normal = ns;
    if (!data_.colors.empty())
        si.vertex_color = data_.colors[idx[0]] * b0 + data_.colors[idx[1]] * b1 + data_.colors[idx[2]] * b2;
    if (!data_.vertex_materials.empty()) {
        si.blends_materials = true;
        si.materials = {data_.vertex_materials[idx[0]], data_.vertex_materials[idx[1]], data_.vertex_materials[idx[2]]};
        si.material_weights = {b0, b1, b2};
    }
    if (detail == InteractionDetail::WithoutTextureCoordinates) return;
    if (!data_.normals.empty())  // unit since construction
        si.curvature =
            triangle_curvature(p0, p1, p2, data_.normals[idx[0]], data_.normals[idx[1]], data_.normals[idx[2]]);
    if (!data_.tangents.empty()) {
        si.tangent = data_.tangents[idx[0]].direction * b0 + data_.tangents[idx[1]].direction * b1 +
                     data_.tangents[idx[2]].direction * b2;
        si.tangent_sign = data_.tangents[idx[0]].sign;
    }
    // Without texture coordinates the barycentric weights stand in for them.
    const bool has_uvs = !data_.uvs.empty();
    const Vec2 uv0 = has_uvs ? data_.uvs[idx[0]] : Vec2(0.0f, 0.0f);
    const Vec2 uv1 = has_uvs ? data_.uvs[idx[1]] : Vec2(1.0f, 0.0f);
    const Vec2 uv2 = has_uvs ? data_.uvs[idx[2]] : Vec2(0.0f, 1.0f);
    si.uv = uv0 * b0 + uv1 * b1 + uv2 * b2;
    const TriangleDerivatives derivatives = triangle_derivatives(p0, p1, p2, uv0, uv1, uv2);
    si.dpdu = derivatives.dpdu;
    si.dpdv = derivatives.dpdv;
}

void TriangleMesh::prepare_sampling() {
    if (triangle_areas_) return;
    std::vector<float> areas(triangle_count());
    float total = 0.0f;
    for (std::size_t t = 0; t < areas.size(); ++t) {
        const uint32_t* idx = &data_.indices[3 * t];
        const Vec3& p0 = data_.positions[idx[0]];
        areas[t] = 0.5f * length(cross(data_.positions[idx[1]] - p0, data_.positions[idx[2]] - p0));
        total += areas[t];
    }
    // A mesh of only degenerate triangles has no area to emit from: area() stays 0.
    if (total > 0.0f && std::isfinite(total)) triangle_areas_.emplace(areas);
}

float TriangleMesh::area() const { return triangle_areas_ ? triangle_areas_->total() : 0.0f; }

std::optional<ShapeSample> TriangleMesh::sample_area(Vec2 u, InteractionDetail detail) const {
    if (!triangle_areas_) return std::nullopt;
    float u_remapped = 0.0f;
    const std::size_t t = triangle_areas_->sample(u.x, nullptr, &u_remapped);
    const std::array<float, 3> b = sample_uniform_triangle(Vec2(u_remapped, u.y));
    const uint32_t* idx = &data_.indices[3 * t];
    const Vec3& p0 = data_.positions[idx[0]];
    const Vec3& p1 = data_.positions[idx[1]];
    const Vec3& p2 = data_.positions[idx[2]];
    ShapeSample s;
    s.p = p0 * b[0] + p1 * b[1] + p2 * b[2];
    s.n = normalize(cross(p1 - p0, p2 - p0));
    if (detail == InteractionDetail::Full)
        s.uv = data_.uvs.empty() ? Vec2(b[1], b[2])
                                 : data_.uvs[idx[0]] * b[0] + data_.uvs[idx[1]] * b[1] + data_.uvs[idx[2]] * b[2];
    s.pdf = 1.0f / triangle_areas_->total();
    return s;
}

std::size_t TriangleMesh::memory_bytes() const {
    return data_.positions.size() * sizeof(Vec3) + data_.indices.size() * sizeof(uint32_t) +
           data_.normals.size() * sizeof(Vec3) + data_.uvs.size() * sizeof(Vec2) + data_.colors.size() * sizeof(Color) +
           data_.vertex_materials.size() * sizeof(uint32_t) + data_.tangents.size() * sizeof(Tangent) +
           bvh_.memory_bytes();
}

void compute_smooth_normals(MeshData& data) {
    data.normals.assign(data.positions.size(), Vec3(0.0f));
    for (std::size_t t = 0; t + 2 < data.indices.size(); t += 3) {
        const uint32_t a = data.indices[t], b = data.indices[t + 1], c = data.indices[t + 2];
        const Vec3 n = cross(data.positions[b] - data.positions[a], data.positions[c] - data.positions[a]);
        data.normals[a] += n;
        data.normals[b] += n;
        data.normals[c] += n;
    }
    for (Vec3& n : data.normals) {
        const float len = length(n);
        n = len > 0.0f ? n / len : Vec3(0.0f);
    }
}

}  // namespace glint
