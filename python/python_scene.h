#pragma once
// glint.Scene: a scene loaded from a file, or described in code (scene_document.h) and built
// when it is first rendered after a change. Either way a render gets a PreparedScene, which
// nothing changes, so renders of it may run at once and outlive the Scene object.

#include "scene_document.h"

#include "glint/image/display_transform.h"
#include "glint/integrators/render_settings.h"
#include "glint/scene/render_scene.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::python {

/// A scene ready to render, with the settings and display transform its description gives.
struct PreparedScene {
    RenderScene scene;
    RenderSettings settings;
    DisplayTransform display;
    std::vector<std::string> warnings;
};

class PythonScene {
public:
    /// An empty description; relative file names in it resolve against `base_dir`.
    explicit PythonScene(std::filesystem::path base_dir);
    /// A description given whole (glint.load_dict).
    PythonScene(DocumentTable document, std::filesystem::path base_dir);
    /// glint.load: any scene file (TOML, glTF, a mesh), prepared at once.
    [[nodiscard]] static PythonScene load(const std::filesystem::path& path);
    /// glint.default_scene: what `glint render` with no scene file renders.
    [[nodiscard]] static PythonScene default_scene();

    /// `[section]` ("camera") takes these keys; throws TypeError for a scene loaded from a file.
    void set(std::string_view section, const py::kwargs& keys);
    /// One more `[[section]]` ("objects") with these keys, and `type` first when given.
    void add(std::string_view section, const py::kwargs& keys, std::string_view type = {});

    /// The scene as it is described now, built (with the GIL released) if it changed since
    /// the last call. Throws glint.SceneError for a mistake in the description.
    [[nodiscard]] std::shared_ptr<const PreparedScene> prepared();

    /// The description as dicts and lists (None for a scene loaded from a file).
    [[nodiscard]] py::object to_dict() const;
    [[nodiscard]] std::string repr() const;

private:
    PythonScene() = default;
    DocumentTable& document(std::string_view method);

    /// Empty for a scene loaded from a file.
    std::optional<DocumentTable> document_;
    std::filesystem::path base_dir_;
    std::string source_;
    std::shared_ptr<const PreparedScene> prepared_;
    /// Counts the changes: a build that another thread's change overtook (the GIL is released
    /// while it runs) is used by its own render but not kept.
    uint64_t version_ = 0;
};

}  // namespace glint::python
