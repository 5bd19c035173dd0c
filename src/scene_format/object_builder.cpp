#include "object_builder.h"

#include "glint/assets/mesh_loader.h"
#include "glint/geometry/cutout_shape.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/scene.h"
#include "glint/scene_format/did_you_mean.h"
#include "glint/scene_format/motion_params.h"
#include "glint/scene_format/registry.h"
#include "glint/scene_format/transform_params.h"

#include <fmt/format.h>

#include <map>

namespace glint {

namespace {

using ShapeLibrary = std::map<std::string, std::shared_ptr<Shape>>;
using MotionKeys = std::optional<std::vector<MotionKey>>;

/// Make objects [first, end) move by `keys`, which placed them at their first key: each
/// keeps its place relative to the keys (a mesh file's parts move as one).
void set_motion(const ParamTable& t, const MotionKeys& keys, uint32_t first, BuildContext& context) {
    if (!keys) return;
    Scene& scene = context.scene();
    const Transform first_from_world = keys->front().transform.inverse();
    const auto end = uint32_t(scene.objects().size());
    for (uint32_t object = first; object < end; ++object) {
        const Transform relative = first_from_world * scene.objects()[object].world_from_object;
        std::vector<MotionKey> placed = *keys;
        for (MotionKey& key : placed) key.transform = key.transform * relative;
        try {
            scene.set_motion(object, AnimatedTransform(std::move(placed)));
        } catch (const std::invalid_argument& e) {
            const char* key = t.find("motion") ? "motion" : "transform_end";
            t.fail(key, fmt::format("an object Glint can move: {}", e.what()));
        }
    }
}

/// A mesh file placed by `[[objects]]`: all its meshes, with its materials or `material`.
void import_file(const ParamTable& t, const std::optional<Transform>& transform, const MotionKeys& keys,
                 BuildContext& context) {
    const auto first = uint32_t(context.scene().objects().size());
    const std::filesystem::path path = context.input_file(t, "file");
    std::optional<uint32_t> override_material;
    if (const ParamValue* m = t.find("material")) override_material = context.material(*m, ValueName(t, "material"));
    t.reject_unknown_keys();
    try {
        const MeshImportResult result = import_mesh_file(context.scene(), path, transform.value_or(Transform()),
                                                         override_material, context.meshes());
        for (const std::string& w : result.warnings) context.warn(t.find("file")->where().to_string() + ": " + w);
    } catch (const std::exception& e) {
        // The importer names the file; add where the scene asked for it.
        throw_scene_error(t.find("file")->where(), fmt::format("cannot import {}: {}", t.name_of("file"), e.what()));
    }
    set_motion(t, keys, first, context);
}

/// The per-vertex materials of a mesh (handout §6.1.1), if it has them.
const std::vector<uint32_t>* vertex_materials(const Shape& shape) {
    const auto* mesh = dynamic_cast<const TriangleMesh*>(&shape);
    return mesh && !mesh->data().vertex_materials.empty() ? &mesh->data().vertex_materials : nullptr;
}

/// A material's `alpha_texture` cuts its object out where the texture's alpha is below
/// `alpha_cutoff`. A triangle mesh tests it inside its own traversal (so the closest kept
/// hit is found at no extra cost); it needs uvs, and a mesh without them is refused rather
/// than drawn uncut. Every other shape is wrapped in a CutoutShape.
std::shared_ptr<Shape> apply_cutout(const ParamTable& t, std::shared_ptr<Shape> shape, const Material& m) {
    auto* mesh = dynamic_cast<TriangleMesh*>(shape.get());
    if (!mesh) return std::make_shared<CutoutShape>(std::move(shape), m.alpha_texture, m.alpha_cutoff);
    if (mesh->data().uvs.empty())
        t.fail("material", fmt::format("a material without alpha_texture for a mesh without uvs: material '{}' cuts "
                                       "out by texture coordinates, which this mesh does not have",
                                       m.name));
    if (mesh->alpha_mask() && mesh->alpha_mask() != m.alpha_texture)
        t.fail("material", "the same alpha_texture as the other objects that place this shape");
    mesh->set_alpha_mask(m.alpha_texture, m.alpha_cutoff);
    return shape;
}

void add_object(const ParamTable& t, const ShapeLibrary& library, BuildContext& context) {
    const MotionKeys keys = read_motion_keys(t);
    std::optional<Transform> transform;
    if (keys)
        transform = keys->front().transform;
    else if (const ParamValue* v = t.find("transform"))
        transform = read_transform(*v, ValueName(t, "transform"));
    std::shared_ptr<Shape> shape;
    if (const ParamValue* ref = t.find("shape")) {
        if (t.find("type")) t.fail("type", "no type for an object that places a named shape (shape = ...)");
        const std::string& name = ref->as_string(ValueName(t, "shape"));
        const auto it = library.find(name);
        if (it == library.end()) {
            std::vector<std::string> names;
            for (const auto& entry : library) names.push_back(entry.first);
            ref->fail(t.name_of("shape"), "the name of a shape in [[shapes]]" + did_you_mean(name, names));
        }
        shape = it->second;
    } else {
        const ShapeType& type = chosen_type(t, shape_types());
        if (type.name == "mesh" && t.find("file")) return import_file(t, transform, keys, context);
        shape = type.create(t, context);
    }
    // A mesh with per-vertex materials takes its first vertex's as the object's (any will
    // do: shading blends the three corners'); other shapes need `material`.
    const std::vector<uint32_t>* per_vertex = vertex_materials(*shape);
    const ParamValue* m = per_vertex ? t.find("material") : &t.require("material", "a material name");
    if (m && per_vertex) t.fail("material", "either one material or per-vertex materials, not both");
    const uint32_t material = m ? context.material(*m, ValueName(t, "material")) : per_vertex->front();
    if (context.scene().material(material).alpha_texture)
        shape = apply_cutout(t, std::move(shape), context.scene().material(material));
    const std::string name = t.string("name", "");
    t.reject_unknown_keys();
    const uint32_t object = context.scene().add_object(std::move(shape), material, transform, name);
    set_motion(t, keys, object, context);
}

}  // namespace

void add_objects(const ParamTable& root, const MoreObjects& more_objects, BuildContext& context) {
    ShapeLibrary library;
    for (const ParamTable* t : root.tables("shapes")) {
        const std::string& name = t->require_string("name");
        if (library.count(name)) t->fail("name", "a name not used by an earlier shape");
        const ShapeType& type = chosen_type(*t, shape_types());
        if (type.name == "mesh" && t->find("file"))
            t->fail("file", "inline mesh data: mesh files are placed directly by [[objects]]");
        library.emplace(name, type.create(*t, context));
        t->reject_unknown_keys();
    }
    for (const ParamTable* t : root.tables("objects")) add_object(*t, library, context);
    if (!more_objects) return;
    while (const std::shared_ptr<const ParamTable> t = more_objects()) {
        add_object(*t, library, context);
        // What build_scene's last check does for the root's tables, before this one goes.
        t->reject_unknown_keys_recursive();
    }
}

}  // namespace glint
