#include "object_builder.h"

#include "glint/geometry/box.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/heightfield.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene_format/did_you_mean.h"
#include "scene_builder.h"
#include "transform_params.h"
#include "glint/math/constants.h"

#include <fmt/format.h>

#include <array>
#include <map>
#include <stdexcept>

namespace glint {

namespace {

constexpr std::array<std::string_view, 8> kShapeTypes{"sphere", "triangle", "mesh",        "quad",
                                                      "plane",  "box",      "heightfield", "disk"};

/// A built shape; meshes with per-vertex materials need no object material.
struct BuiltShape {
    std::shared_ptr<Shape> shape;
    bool per_vertex_materials = false;
    uint32_t first_material = 0;
};

std::string element(const ParamTable& t, std::string_view key, std::size_t i) {
    return fmt::format("{}[{}]", t.name_of(key), i);
}

std::vector<Vec3> vec3_list(const ParamTable& t, std::string_view key, bool required) {
    std::vector<Vec3> out;
    const ParamValue* v = required ? &t.require(key, "an array of [x, y, z]") : t.find(key);
    if (!v) return out;
    const auto& a = v->as_array(t.name_of(key));
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(a[i].as_vec3(element(t, key, i)));
    return out;
}

std::vector<Vec2> vec2_list(const ParamTable& t, std::string_view key) {
    std::vector<Vec2> out;
    if (const ParamValue* v = t.find(key)) {
        const auto& a = v->as_array(t.name_of(key));
        for (std::size_t i = 0; i < a.size(); ++i) out.push_back(a[i].as_vec2(element(t, key, i)));
    }
    return out;
}

/// Per-vertex material names (handout §6.1.1) as scene material indices.
std::vector<uint32_t> material_list(const ParamTable& t, const Scene& scene) {
    std::vector<uint32_t> out;
    if (const ParamValue* v = t.find("materials")) {
        const auto& a = v->as_array(t.name_of("materials"));
        for (std::size_t i = 0; i < a.size(); ++i)
            out.push_back(material_by_name(scene, a[i], element(t, "materials", i)));
    }
    return out;
}

/// Flat `[0, 1, 2, 0, 2, 3]` or nested `[[0, 1, 2], [0, 2, 3]]`; each index remembers its value.
std::vector<const ParamValue*> index_values(const ParamTable& t) {
    std::vector<const ParamValue*> out;
    const ParamValue& v = t.require("indices", "vertex indices, three per triangle");
    for (const ParamValue& e : v.as_array(t.name_of("indices"))) {
        if (!e.is_array()) {
            out.push_back(&e);
            continue;
        }
        const auto& triple = e.as_array(t.name_of("indices"));
        if (triple.size() != 3) e.fail(t.name_of("indices") + " entry", "three vertex indices");
        for (const ParamValue& i : triple) out.push_back(&i);
    }
    if (out.empty() || out.size() % 3 != 0) v.fail(t.name_of("indices"), "vertex indices, three per triangle");
    return out;
}

bool degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = b - a, e2 = c - a;
    // sin of the corner angle below float precision: the corners are collinear or coincide.
    return !(length(cross(e1, e2)) > 1e-7f * length(e1) * length(e2));
}

BuiltShape finish_mesh(const ParamTable& t, MeshData data, std::string_view list_key) {
    const std::size_t n = data.positions.size();
    auto check_size = [&](std::string_view key, std::size_t size) {
        if (size != 0 && size != n) t.fail(key, fmt::format("one entry per vertex ({})", n));
    };
    check_size("normals", data.normals.size());
    check_size("uvs", data.uvs.size());
    check_size("materials", data.vertex_materials.size());
    BuiltShape built;
    built.per_vertex_materials = !data.vertex_materials.empty();
    if (built.per_vertex_materials) built.first_material = data.vertex_materials[0];
    try {
        built.shape = std::make_shared<TriangleMesh>(std::move(data), t.string("name", ""));
    } catch (const std::invalid_argument& e) {
        t.fail(list_key, fmt::format("valid mesh data ({})", e.what()));
    }
    return built;
}

BuiltShape triangle(const ParamTable& t, const Scene& scene) {
    MeshData data;
    data.positions = vec3_list(t, "vertices", true);
    if (data.positions.size() != 3) t.fail("vertices", "three corners [[x, y, z], [x, y, z], [x, y, z]]");
    if (degenerate(data.positions[0], data.positions[1], data.positions[2]))
        throw_scene_error(t.find("vertices")->where(),
                          t.name_of("vertices") +
                              " is a degenerate triangle (its corners are collinear or coincide); "
                              "expected three corners that span a non-zero area");
    data.indices = {0, 1, 2};
    data.normals = vec3_list(t, "normals", false);
    data.uvs = vec2_list(t, "uvs");
    data.vertex_materials = material_list(t, scene);
    return finish_mesh(t, std::move(data), "vertices");
}

BuiltShape inline_mesh(const ParamTable& t, const Scene& scene) {
    MeshData data;
    data.positions = vec3_list(t, "positions", true);
    const auto indices = index_values(t);
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const int64_t i = indices[k]->as_integer(t.name_of("indices"));
        if (i < 0 || std::size_t(i) >= data.positions.size())
            indices[k]->fail(t.name_of("indices") + " entry",
                             fmt::format("a vertex index from 0 to {}", int64_t(data.positions.size()) - 1));
        data.indices.push_back(uint32_t(i));
    }
    for (std::size_t tri = 0; tri < data.indices.size() / 3; ++tri) {
        const uint32_t* v = &data.indices[3 * tri];
        if (degenerate(data.positions[v[0]], data.positions[v[1]], data.positions[v[2]]))
            throw_scene_error(indices[3 * tri]->where(),
                              fmt::format("triangle {} (vertices {}, {}, {}) of {} is degenerate (its corners are "
                                          "collinear or coincide); expected corners that span a non-zero area",
                                          tri, v[0], v[1], v[2], t.path()));
    }
    data.normals = vec3_list(t, "normals", false);
    data.uvs = vec2_list(t, "uvs");
    data.vertex_materials = material_list(t, scene);
    return finish_mesh(t, std::move(data), "positions");
}

std::shared_ptr<Shape> heightfield(const ParamTable& t) {
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
        for (std::size_t i = 0; i < values.size(); ++i) heights[i] += values[i]->as_float(element(t, "heights", i));
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

}  // namespace

std::shared_ptr<Shape> read_simple_shape(const ParamTable& t, const std::string& type, const Vec3& disk_normal) {
    if (type == "sphere") {
        const Vec3 center = t.vec3("center", Vec3(0.0f));
        const float radius = t.require_number("radius");
        if (!(radius > 0.0f)) t.fail("radius", "a positive radius");
        return std::make_shared<Sphere>(center, radius);
    }
    if (type == "quad") {
        const Vec3 corner = t.require_vec3("corner"), u = t.require_vec3("edge_u"), v = t.require_vec3("edge_v");
        if (!(length(cross(u, v)) > 0.0f))
            t.fail("edge_v", "an edge that is non-zero and not parallel to edge_u (a quad of positive area)");
        return std::make_shared<Quad>(corner, u, v);
    }
    if (type == "plane") {
        const Vec3 center = t.vec3("center", Vec3(0.0f));
        const ParamValue& s = t.require("size", "the extent along x and z: a number or [sx, sz]");
        const Vec2 size = s.is_number() ? Vec2(s.as_float(t.name_of("size")), s.as_float(t.name_of("size")))
                                        : s.as_vec2(t.name_of("size"));
        if (!(size.x > 0.0f && size.y > 0.0f)) t.fail("size", "positive extents");
        // Facing +y, u along +x and v along -z, so textures read left to right seen from above.
        const Vec3 u(size.x, 0.0f, 0.0f), v(0.0f, 0.0f, -size.y);
        return std::make_shared<Quad>(center - u * 0.5f - v * 0.5f, u, v);
    }
    if (type == "disk") {
        const Vec3 normal = t.vec3("normal", disk_normal);
        if (!(length(normal) > 0.0f)) t.fail("normal", "a non-zero direction the disk faces");
        const float radius = t.require_number("radius");
        if (!(radius > 0.0f)) t.fail("radius", "a positive radius");
        return std::make_shared<Disk>(t.vec3("center", Vec3(0.0f)), normal, radius);
    }
    if (type == "box") {
        const Vec3 lo = t.require_vec3("min"), hi = t.require_vec3("max");
        if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) t.fail("max", "a corner above min on every axis");
        return std::make_shared<Box>(lo, hi);
    }
    return heightfield(t);
}

namespace {

BuiltShape build_shape(const ParamTable& t, const std::string& type, const Scene& scene) {
    if (type == "triangle") return triangle(t, scene);
    if (type == "mesh") return inline_mesh(t, scene);
    return {read_simple_shape(t, type), false, 0};
}

void import_file(const ParamTable& t, const std::filesystem::path& base_dir, const std::optional<Transform>& transform,
                 Scene& scene, MeshCache& meshes, std::vector<std::string>& warnings) {
    const std::filesystem::path path = resolve_input_file(t, "file", base_dir);
    std::optional<uint32_t> override_material;
    if (const ParamValue* m = t.find("material"))
        override_material = material_by_name(scene, *m, t.name_of("material"));
    t.reject_unknown_keys();
    try {
        const MeshImportResult result =
            import_mesh_file(scene, path, transform.value_or(Transform()), override_material, meshes);
        for (const std::string& w : result.warnings) warnings.push_back(t.find("file")->where().to_string() + ": " + w);
    } catch (const std::exception& e) {
        // The importer names the file; add where the scene asked for it.
        throw_scene_error(t.find("file")->where(), fmt::format("cannot import {}: {}", t.name_of("file"), e.what()));
    }
}

using ShapeLibrary = std::map<std::string, BuiltShape>;

void add_object(const ParamTable& t, const ShapeLibrary& library, const std::filesystem::path& base_dir, Scene& scene,
                MeshCache& meshes, std::vector<std::string>& warnings) {
    std::optional<Transform> transform;
    if (const ParamValue* v = t.find("transform")) transform = read_transform(*v, t.name_of("transform"));
    BuiltShape built;
    if (const ParamValue* ref = t.find("shape")) {
        if (t.find("type")) t.fail("type", "no type for an object that places a named shape (shape = ...)");
        const std::string& name = ref->as_string(t.name_of("shape"));
        const auto it = library.find(name);
        if (it == library.end()) {
            std::vector<std::string> names;
            for (const auto& entry : library) names.push_back(entry.first);
            ref->fail(t.name_of("shape"), "the name of a shape in [[shapes]]" + did_you_mean(name, names));
        }
        built = it->second;
    } else {
        const std::string type = t.choice("type", kShapeTypes, "");
        if (type == "mesh" && t.find("file")) return import_file(t, base_dir, transform, scene, meshes, warnings);
        built = build_shape(t, type, scene);
    }
    uint32_t material = built.first_material;
    const ParamValue* m = built.per_vertex_materials ? t.find("material") : &t.require("material", "a material name");
    if (m && built.per_vertex_materials) t.fail("material", "either one material or per-vertex materials, not both");
    if (m) material = material_by_name(scene, *m, t.name_of("material"));
    const std::string name = t.string("name", "");
    t.reject_unknown_keys();
    scene.add_object(built.shape, material, transform, name);
}

}  // namespace

uint32_t material_by_name(const Scene& scene, const ParamValue& value, std::string_view what) {
    const std::string& name = value.as_string(what);
    if (const auto index = scene.find_material(name)) return *index;
    std::vector<std::string> names;
    for (const Material& m : scene.materials()) names.push_back(m.name);
    value.fail(what, "the name of a material in [[materials]]" + did_you_mean(name, names));
}

void add_objects(const ParamTable& root, const std::filesystem::path& base_dir, Scene& scene, MeshCache& meshes,
                 std::vector<std::string>& warnings) {
    ShapeLibrary library;
    for (const ParamTable* t : root.tables("shapes")) {
        const std::string& name = t->require_string("name");
        if (library.count(name)) t->fail("name", "a name not used by an earlier shape");
        const std::string type = t->choice("type", kShapeTypes, "");
        if (type == "mesh" && t->find("file"))
            t->fail("file", "inline mesh data: mesh files are placed directly by [[objects]]");
        library.emplace(name, build_shape(*t, type, scene));
        t->reject_unknown_keys();
    }
    for (const ParamTable* t : root.tables("objects")) add_object(*t, library, base_dir, scene, meshes, warnings);
}

}  // namespace glint
