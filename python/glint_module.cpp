// The Python module `glint`: load a scene or describe one in code, render it, and hand the
// pixels to NumPy without a copy. Every call goes to libglint, the library the command line
// uses (no second implementation): a render here and `glint render` of the same scene and
// settings give the same floats. docs/python.md shows it in use.

#include "python_image.h"
#include "python_render.h"
#include "python_scene.h"

#include "glint/diagnostics.h"
#include "glint/image/image_io.h"
#include "glint/scene_format/registry.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace py = pybind11;
using glint::python::PythonImage;
using glint::python::PythonScene;

namespace {

/// Where relative file names of a scene described in code resolve: `base_dir`, or the
/// working directory at the time of the call.
std::filesystem::path folder_or_cwd(const std::optional<std::filesystem::path>& base_dir) {
    return base_dir ? *base_dir : std::filesystem::current_path();
}

PythonScene load_dict(const py::dict& description, const std::optional<std::filesystem::path>& base_dir) {
    const glint::SourceLocation where = glint::python::python_call_site();
    glint::python::DocumentValue document = glint::python::from_python(description, "", where);
    PythonScene scene(std::get<glint::python::DocumentTable>(std::move(document.data)), folder_or_cwd(base_dir));
    // Built at once, as load() builds: a mistake is raised here.
    (void)scene.prepared();
    return scene;
}

void bind_scene(py::module_& m) {
    auto scene = py::class_<PythonScene>(m, "Scene", R"(A scene to render, loaded from a file or described in code.

Described in code, its methods take the keys of the TOML format (docs/scene-format.md) as
keywords, with the same names and defaults:

    scene = glint.Scene()
    scene.set_camera(position=(0, 1, 6), look_at=(0, 1, 0), fov=40)
    scene.add_material(name="red", diffuse=(0.8, 0.1, 0.1))
    scene.add_sphere(center=(0, 1, 0), radius=1, material="red")
    scene.add_light(type="point", position=(4, 6, 4), intensity=60, falloff="inverse_square")

A mistake raises glint.SceneError naming the line of Python that gave the value.)");
    scene.def(py::init([](const std::optional<std::filesystem::path>& base_dir) {
                  return PythonScene(folder_or_cwd(base_dir));
              }),
              py::arg("base_dir") = py::none(),
              "An empty scene; relative file names (meshes, textures) resolve against base_dir, by default the "
              "working directory.");
    for (const std::string_view section : {"render", "display", "camera", "background", "world"}) {
        const std::string name(section);
        scene.def(("set_" + name).c_str(), [name](PythonScene& s, const py::kwargs& keys) { s.set(name, keys); },
                  ("Set keys of the [" + name + "] table; a key set again takes the new value.").c_str());
    }
    for (const auto& [method, section] :
         {std::pair{"add_texture", "textures"}, std::pair{"add_material", "materials"},
          std::pair{"add_light", "lights"}, std::pair{"add_shape", "shapes"}, std::pair{"add_object", "objects"}}) {
        const std::string name(section);
        scene.def(
            method, [name](PythonScene& s, const py::kwargs& keys) { s.add(name, keys); },
            ("Add a [[" + name + "]] table with these keys.").c_str());
    }
    // One method per shape type of the registry: a shape added there is placed from Python too.
    for (const glint::ShapeType& type : glint::shape_types()) {
        const std::string name(type.name);
        scene.def(
            ("add_" + name).c_str(), [name](PythonScene& s, const py::kwargs& keys) { s.add("objects", keys, name); },
            ("Place a " + name + ": add_object(type=\"" + name + "\", ...) (a mesh from a file: file=PATH).").c_str());
    }
    scene
        .def("to_dict", &PythonScene::to_dict,
             "The description as dicts and lists, as tomllib reads the same scene in TOML (None for a scene loaded "
             "from a file).")
        .def("__repr__", &PythonScene::repr)
        .def_property_readonly(
            "width", [](PythonScene& s) { return s.prepared()->settings.width; }, "The image width in pixels.")
        .def_property_readonly(
            "height", [](PythonScene& s) { return s.prepared()->settings.height; }, "The image height in pixels.")
        .def_property_readonly(
            "spp",
            [](PythonScene& s) {
                const uint32_t n = s.prepared()->settings.samples_per_axis;
                return n * n;
            },
            "Samples per pixel.")
        .def_property_readonly(
            "integrator", [](PythonScene& s) { return s.prepared()->settings.integrator; }, "The integrator.")
        .def_property_readonly(
            "warnings", [](PythonScene& s) { return s.prepared()->warnings; }, "What the loader worked around.");
}

void bind_image(py::module_& m) {
    py::class_<PythonImage>(m, "Image", py::buffer_protocol(),
                            "Linear float pixels; np.asarray(image) views them, shape (height, width, channels).")
        .def(py::init(&glint::python::image_from_array), py::arg("pixels"), py::arg("channels") = py::none(),
             "An image holding a copy of `pixels`, shape (height, width) or (height, width, channels); `channels` "
             "names them (Y, R G B or R G B A by default).")
        .def_buffer(&glint::python::image_buffer)
        .def_property_readonly("width", [](const PythonImage& i) { return i.image.width; })
        .def_property_readonly("height", [](const PythonImage& i) { return i.image.height; })
        .def_property_readonly(
            "channels", [](const PythonImage& i) { return i.image.channel_names; }, "The channels' names.")
        .def("channel", &glint::python::image_channel, py::arg("name"),
             "Channel `name` (\"R\", \"albedo.G\", \"Z\", ...) as a (height, width) array over the image's pixels.")
        .def("save", &glint::python::save_image, py::arg("path"),
             "Write the image as `glint render -o PATH` would: EXR, HDR and PFM keep the floats; PNG and JPEG get "
             "the scene's exposure and tone curve in sRGB. Written under a temporary name, then renamed.");
}

}  // namespace

PYBIND11_MODULE(glint, m) {
    m.doc() = "Glint, a ray tracer: load a scene or describe one in code, render it, get its pixels as NumPy arrays.";
    py::register_exception<glint::SceneError>(m, "SceneError");
    py::register_exception<glint::ImageError>(m, "ImageError");
    bind_scene(m);
    bind_image(m);

    m.def("load", &PythonScene::load, py::arg("path"),
          "Load a scene file: TOML, glTF/GLB, or a mesh file (OBJ, PLY, ...) under a framing camera. Raises "
          "glint.SceneError with the file, line and column of a mistake.");
    m.def("default_scene", &PythonScene::default_scene,
          "The built-in scene `glint render` renders when given no file: the seminar's spheres at 4 spp.");
    m.def("load_dict", &load_dict, py::arg("description"), py::arg("base_dir") = py::none(),
          "A scene described by a dict of the TOML format's tables (tomllib.load of a scene file gives one). "
          "Relative file names resolve against base_dir, by default the working directory. Raises glint.SceneError "
          "naming this call's line for a mistake.");
    m.def("render", &glint::python::render, py::arg("scene"), py::kw_only(), py::arg("progress") = py::none(),
          "render(scene, *, progress=None, **settings) -> Image. Render `scene`; a keyword overrides the scene's "
          "setting as the option of the same name does for `glint render` (light_samples for --light-samples): "
          "width, height, spp (a square number), depth, threads, seed, integrator, filter, filter_radius, "
          "light_samples, glossy_samples, mis, aov (\"albedo,depth\": extra channels), adaptive, "
          "adaptive_threshold, crop (\"x0,y0,x1,y1\": the image is that region; save() to EXR keeps its place). "
          "progress=True draws a bar on sys.stderr; a callable gets (done, total) tiles. "
          "Ctrl-C stops the render and raises KeyboardInterrupt. Raises ValueError for a value out of range, "
          "TypeError for an unknown keyword.");
    m.def("explain", &glint::python::explain, py::arg("scene"), py::kw_only(), py::arg("pixel"),
          py::arg("sample") = py::none(),
          "explain(scene, *, pixel=(x, y), sample=None, **settings) -> dict. Why pixel (x, y) (from the top left) "
          "has its colour: its value and every sample's rays as `glint explain --json` prints them (the rays of "
          "sample `sample` only, when given). Takes render()'s settings.");
}
