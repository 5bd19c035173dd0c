// The scene-file factories of TriangleMesh: `type = "triangle"` and inline `type = "mesh"`
// (a mesh file, `type = "mesh"` with `file`, is placed by the objects section through
// asset import instead: it may hold many meshes and materials).
#include "glint/geometry/triangle_mesh.h"

#include "glint/scene_format/build_context.h"

#include <fmt/format.h>

#include <stdexcept>

namespace glint {

namespace {

/// Per-vertex material names (handout §6.1.1) as scene material indices.
std::vector<uint32_t> material_list(const ParamTable& t, const BuildContext& context) {
    std::vector<uint32_t> out;
    if (const ParamValue* v = t.find("materials")) {
        const auto& a = v->as_array(t.name_of("materials"));
        for (std::size_t i = 0; i < a.size(); ++i)
            out.push_back(context.material(a[i], fmt::format("{}[{}]", t.name_of("materials"), i)));
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

/// Normals, uvs and per-vertex materials (each optional, one per vertex), then the mesh.
std::shared_ptr<Shape> finish_mesh(const ParamTable& t, const BuildContext& context, MeshData data,
                                   std::string_view list_key) {
    data.normals = t.vec3_list("normals", false);
    data.uvs = t.vec2_list("uvs");
    data.vertex_materials = material_list(t, context);
    const std::size_t n = data.positions.size();
    auto check_size = [&](std::string_view key, std::size_t size) {
        if (size != 0 && size != n) t.fail(key, fmt::format("one entry per vertex ({})", n));
    };
    check_size("normals", data.normals.size());
    check_size("uvs", data.uvs.size());
    check_size("materials", data.vertex_materials.size());
    try {
        return std::make_shared<TriangleMesh>(std::move(data), t.string("name", ""));
    } catch (const std::invalid_argument& e) {
        t.fail(list_key, fmt::format("valid mesh data ({})", e.what()));
    }
}

}  // namespace

std::shared_ptr<Shape> TriangleMesh::triangle_from_params(const ParamTable& t, const BuildContext& context) {
    MeshData data;
    data.positions = t.vec3_list("vertices", true);
    if (data.positions.size() != 3) t.fail("vertices", "three corners [[x, y, z], [x, y, z], [x, y, z]]");
    if (degenerate(data.positions[0], data.positions[1], data.positions[2]))
        throw_scene_error(t.find("vertices")->where(),
                          t.name_of("vertices") +
                              " is a degenerate triangle (its corners are collinear or coincide); "
                              "expected three corners that span a non-zero area");
    data.indices = {0, 1, 2};
    return finish_mesh(t, context, std::move(data), "vertices");
}

std::shared_ptr<Shape> TriangleMesh::from_params(const ParamTable& t, const BuildContext& context) {
    MeshData data;
    data.positions = t.vec3_list("positions", true);
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
    return finish_mesh(t, context, std::move(data), "positions");
}

}  // namespace glint
