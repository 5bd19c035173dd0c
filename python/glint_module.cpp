// The Python module `glint`: load a scene, render it, and hand the pixels to NumPy without a
// copy. Every call goes to libglint, the library the command line uses (no second
// implementation): a render here and `glint render` of the same scene and settings give the
// same floats.

#include "glint/image/aov_film.h"
#include "glint/image/display_transform.h"
#include "glint/image/film.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/render_overrides.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_file.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace {

/// A scene file, loaded and prepared for rendering once: every render of it shares the
/// render scene (which nothing changes), with its own settings.
struct PythonScene {
    std::shared_ptr<const glint::RenderScene> scene;
    glint::RenderSettings settings;
    glint::DisplayTransform display;
    std::vector<std::string> warnings;
};

/// A rendered image, its channels named (Film::to_image, AovFilm::append_to), and the
/// display transform its scene asks for (used by save() for PNG and JPEG, as `glint render`
/// uses it).
struct PythonImage {
    glint::Image image;
    glint::DisplayTransform display;
};

PythonScene load(const std::filesystem::path& path) {
    glint::SceneFile file = glint::load_scene_file(path);
    PythonScene s;
    s.settings = file.loaded.settings;
    s.display = file.loaded.display;
    s.warnings = std::move(file.loaded.warnings);
    s.scene = std::make_shared<const glint::RenderScene>(std::move(file.loaded.scene));
    return s;
}

/// The settings render() takes as keywords: the command line's overrides, by the same
/// names with "_" for "-" (option_name's Keyword spelling).
using Overrides = glint::RenderOverrides;
struct Keyword {
    std::string_view name;
    std::variant<std::optional<int64_t> Overrides::*, std::optional<std::string> Overrides::*,
                 std::optional<double> Overrides::*, bool Overrides::*>
        field;
};
const std::array<Keyword, 15> kKeywords = {{
    {"width", &Overrides::width},
    {"height", &Overrides::height},
    {"spp", &Overrides::spp},
    {"depth", &Overrides::depth},
    {"threads", &Overrides::threads},
    {"seed", &Overrides::seed},
    {"light_samples", &Overrides::light_samples},
    {"glossy_samples", &Overrides::glossy_samples},
    {"integrator", &Overrides::integrator},
    {"filter", &Overrides::filter},
    {"mis", &Overrides::mis},
    {"aov", &Overrides::aov},
    {"filter_radius", &Overrides::filter_radius},
    {"adaptive_threshold", &Overrides::adaptive_threshold},
    {"adaptive", &Overrides::adaptive},
}};

/// Keyword arguments as overrides: each value's type is checked here, its value by
/// apply_overrides, as for `glint render`.
Overrides overrides_from(const py::kwargs& keywords) {
    Overrides overrides;
    for (const auto& [key, value] : keywords) {
        const auto name = py::cast<std::string>(key);
        const auto keyword =
            std::find_if(kKeywords.begin(), kKeywords.end(), [&](const Keyword& k) { return k.name == name; });
        if (keyword == kKeywords.end())
            throw py::type_error("render() got an unexpected keyword argument '" + name + "'");
        if (value.is_none()) continue;
        // pybind11's casts refuse a value of the wrong type (a string for a number, 2.5 for
        // an integer); said as a TypeError naming the keyword.
        const auto cast = [&]<class T>(T& target) {
            try {
                target = py::cast<T>(value);
            } catch (const py::cast_error&) {
                throw py::type_error(name + ": expected " +
                                     (std::is_same_v<T, bool>          ? "True or False"
                                      : std::is_same_v<T, std::string> ? "a string"
                                      : std::is_same_v<T, double>      ? "a number"
                                                                       : "an integer") +
                                     "; got " + py::cast<std::string>(py::repr(value)));
            }
        };
        std::visit(
            [&](auto field) {
                auto& target = overrides.*field;
                using Target = std::remove_reference_t<decltype(target)>;
                if constexpr (std::is_same_v<Target, bool>) {
                    cast(target);
                } else {
                    typename Target::value_type v{};
                    cast(v);
                    target = std::move(v);
                }
            },
            keyword->field);
    }
    return overrides;
}

PythonImage render(const PythonScene& scene, const py::kwargs& keywords) {
    glint::RenderSettings settings = scene.settings;
    glint::apply_overrides(overrides_from(keywords), settings, glint::OptionSpelling::Keyword);
    glint::Film film(settings.width, settings.height);
    std::optional<glint::AovFilm> aovs;
    if (!settings.aovs.empty()) aovs.emplace(settings.width, settings.height, settings.aovs);
    const std::unique_ptr<glint::Integrator> renderer = glint::make_integrator(settings);
    {
        // The render runs on Glint's threads; other Python threads go on meanwhile (and
        // may drop the scene: this call holds its own reference to the render scene).
        const std::shared_ptr<const glint::RenderScene> held = scene.scene;
        const py::gil_scoped_release release;
        renderer->render(*held, settings, film, {}, nullptr, nullptr, aovs ? &*aovs : nullptr);
    }
    const glint::Image beauty = film.to_image();
    return {aovs ? aovs->append_to(beauty) : beauty, scene.display};
}

/// Channel `name` of `image` as a (height, width) array over the image's own pixels.
py::array channel(const py::object& self, const std::string& name) {
    const PythonImage& img = py::cast<const PythonImage&>(self);
    const std::vector<std::string>& names = img.image.channel_names;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        throw py::key_error("no channel '" + name + "'; the image has " + list);
    }
    const auto f = py::ssize_t(sizeof(float)), c = py::ssize_t(img.image.channels);
    // `self` as the base keeps the image alive while the array lives.
    return py::array(py::dtype::of<float>(), {py::ssize_t(img.image.height), py::ssize_t(img.image.width)},
                     {f * c * img.image.width, f * c}, img.image.pixels.data() + (it - names.begin()), self);
}

void save(const PythonImage& image, const std::filesystem::path& path) {
    glint::WriteOptions options;
    options.tone_curve = image.display.tone_curve;
    options.exposure = glint::exposure_stops(image.display.exposure, image.image);
    glint::write_image(path, image.image, options);
}

}  // namespace

PYBIND11_MODULE(glint, m) {
    m.doc() = "Glint, a ray tracer: load a scene, render it, get its pixels as a NumPy array.";
    py::register_exception<glint::SceneError>(m, "SceneError");
    py::register_exception<glint::ImageError>(m, "ImageError");

    py::class_<PythonScene>(m, "Scene", "A loaded scene, ready to render any number of times.")
        .def_property_readonly(
            "width", [](const PythonScene& s) { return s.settings.width; }, "The scene's image width in pixels.")
        .def_property_readonly(
            "height", [](const PythonScene& s) { return s.settings.height; }, "The scene's image height in pixels.")
        .def_property_readonly(
            "spp", [](const PythonScene& s) { return s.settings.samples_per_axis * s.settings.samples_per_axis; },
            "The scene's samples per pixel.")
        .def_property_readonly(
            "integrator", [](const PythonScene& s) { return s.settings.integrator; }, "The scene's integrator.")
        .def_readonly("warnings", &PythonScene::warnings, "What the loader worked around.");

    py::class_<PythonImage>(m, "Image", py::buffer_protocol(),
                            "Linear float pixels; np.asarray(image) views them, shape (height, width, channels).")
        .def_buffer([](PythonImage& img) {
            const auto c = py::ssize_t(img.image.channels), w = py::ssize_t(img.image.width);
            const auto f = py::ssize_t(sizeof(float));
            return py::buffer_info(img.image.pixels.data(), f, py::format_descriptor<float>::format(), 3,
                                   {py::ssize_t(img.image.height), w, c}, {f * c * w, f * c, f});
        })
        .def_property_readonly("width", [](const PythonImage& i) { return i.image.width; })
        .def_property_readonly("height", [](const PythonImage& i) { return i.image.height; })
        .def_property_readonly(
            "channels", [](const PythonImage& i) { return i.image.channel_names; }, "The channels' names.")
        .def("channel", &channel, py::arg("name"),
             "Channel `name` (\"R\", \"albedo.G\", \"Z\", ...) as a (height, width) array over the image's pixels.")
        .def("save", &save, py::arg("path"),
             "Write the image as `glint render -o PATH` would: EXR, HDR and PFM keep the floats; PNG and JPEG get "
             "the scene's exposure and tone curve in sRGB. Written under a temporary name, then renamed.");

    m.def("load", &load, py::arg("path"),
          "Load a scene file: TOML, glTF/GLB, or a mesh file (OBJ, PLY, ...) under a framing camera. Raises "
          "glint.SceneError with the file, line and column of a mistake.");
    m.def("render", &render, py::arg("scene"),
          "render(scene, **settings) -> Image. Render `scene`; a keyword overrides the scene's setting as the "
          "option of the same name does for `glint render` (light_samples for --light-samples): width, height, "
          "spp (a square number), depth, threads, seed, integrator, filter, filter_radius, light_samples, "
          "glossy_samples, mis, aov (\"albedo,depth\": extra channels), adaptive, adaptive_threshold. Raises "
          "ValueError for a value out of range, TypeError for an unknown keyword.");
}
