#include "python_scene.h"

#include "glint/scene/default_scene.h"
#include "glint/scene_file.h"
#include "glint/scene_format/scene_builder.h"

#include <utility>

namespace glint::python {

namespace {

/// The loader's warnings, as Python warnings (`glint render` prints them as "warning: ...").
std::shared_ptr<const PreparedScene> prepare(LoadedScene loaded) {
    for (const std::string& warning : loaded.warnings)
        if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
    return std::make_shared<const PreparedScene>(PreparedScene{RenderScene(std::move(loaded.scene)), loaded.settings,
                                                               loaded.display, std::move(loaded.warnings)});
}

}  // namespace

PythonScene::PythonScene(std::filesystem::path base_dir)
    : document_(DocumentTable{}), base_dir_(std::move(base_dir)), source_("built in code") {}

PythonScene::PythonScene(DocumentTable document, std::filesystem::path base_dir)
    : document_(std::move(document)), base_dir_(std::move(base_dir)), source_("from a dict") {}

PythonScene PythonScene::load(const std::filesystem::path& path) {
    PythonScene scene;
    scene.source_ = path.string();
    SceneFile file;
    {
        const py::gil_scoped_release release;
        file = load_scene_file(path);
    }
    scene.prepared_ = prepare(std::move(file.loaded));
    return scene;
}

PythonScene PythonScene::default_scene() {
    PythonScene scene;
    scene.source_ = "the built-in scene";
    scene.prepared_ = prepare(make_default_scene());
    return scene;
}

DocumentTable& PythonScene::document(std::string_view method) {
    if (!document_)
        throw py::type_error(
            std::string(method) + ": " + source_ +
            " is not described in code; describe a scene in code with glint.Scene() or glint.load_dict()");
    prepared_.reset();
    ++version_;
    return *document_;
}

void PythonScene::set(std::string_view section, const py::kwargs& keys) {
    const SourceLocation where = python_call_site();
    DocumentTable table = table_from_keywords(keys, std::string(section), where);
    merge_into_section(document("set_" + std::string(section)), section, std::move(table), where);
}

void PythonScene::add(std::string_view section, const py::kwargs& keys, std::string_view type) {
    const SourceLocation where = python_call_site();
    DocumentTable& root = document("add to " + std::string(section));
    DocumentTable table;
    if (!type.empty()) {
        if (keys.contains("type"))
            throw py::type_error("add_" + std::string(type) + "() got the keyword 'type'; its type is '" +
                                 std::string(type) + "'");
        table.emplace_back("type", DocumentValue{std::string(type), where});
    }
    // Named as the TOML loader names the same table: "objects[3]".
    const std::string name = std::string(section) + "[" + std::to_string(section_size(root, section)) + "]";
    for (auto& entry : table_from_keywords(keys, name, where)) table.push_back(std::move(entry));
    append_to_section(root, section, std::move(table), where);
}

std::shared_ptr<const PreparedScene> PythonScene::prepared() {
    if (prepared_) return prepared_;
    const std::shared_ptr<const ParamTable> root = to_param_table(*document_);
    const uint64_t version = version_;
    LoadedScene loaded;
    {
        const py::gil_scoped_release release;
        loaded = build_scene(*root, base_dir_);
    }
    std::shared_ptr<const PreparedScene> built = prepare(std::move(loaded));
    if (version == version_) prepared_ = built;
    return built;
}

py::object PythonScene::to_dict() const {
    if (!document_) return py::none();
    return to_python(*document_);
}

std::string PythonScene::repr() const { return "<glint.Scene " + source_ + ">"; }

}  // namespace glint::python
