#include "python_render.h"

#include "interruptible_call.h"

#include "glint/image/aov_film.h"
#include "glint/image/film.h"
#include "glint/image/frame_assembly.h"
#include "glint/integrators/explanation_format.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/render_overrides.h"

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace glint::python {

namespace {

/// The settings render() and explain() take as keywords: the command line's overrides, by
/// the same names with "_" for "-" (option_name's Keyword spelling).
struct Keyword {
    std::string_view name;
    std::variant<std::optional<int64_t> RenderOverrides::*, std::optional<std::string> RenderOverrides::*,
                 std::optional<double> RenderOverrides::*, bool RenderOverrides::*>
        field;
};
const std::array<Keyword, 16> kKeywords = {{
    {"width", &RenderOverrides::width},
    {"height", &RenderOverrides::height},
    {"spp", &RenderOverrides::spp},
    {"depth", &RenderOverrides::depth},
    {"threads", &RenderOverrides::threads},
    {"seed", &RenderOverrides::seed},
    {"light_samples", &RenderOverrides::light_samples},
    {"glossy_samples", &RenderOverrides::glossy_samples},
    {"integrator", &RenderOverrides::integrator},
    {"filter", &RenderOverrides::filter},
    {"mis", &RenderOverrides::mis},
    {"aov", &RenderOverrides::aov},
    {"crop", &RenderOverrides::crop},
    {"filter_radius", &RenderOverrides::filter_radius},
    {"adaptive_threshold", &RenderOverrides::adaptive_threshold},
    {"adaptive", &RenderOverrides::adaptive},
}};

/// Keyword arguments as overrides: each value's type is checked here, its value by
/// apply_overrides, as for `glint render`.
RenderOverrides overrides_from(const py::kwargs& keywords, std::string_view function) {
    RenderOverrides overrides;
    for (const auto& [key, value] : keywords) {
        const auto name = py::cast<std::string>(key);
        const auto keyword =
            std::find_if(kKeywords.begin(), kKeywords.end(), [&](const Keyword& k) { return k.name == name; });
        if (keyword == kKeywords.end())
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name + "'");
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

RenderSettings settings_for(const PreparedScene& scene, const py::kwargs& keywords, std::string_view function) {
    RenderSettings settings = scene.settings;
    apply_overrides(overrides_from(keywords, function), settings, OptionSpelling::Keyword);
    return settings;
}

}  // namespace

PythonImage render(PythonScene& scene, const py::object& progress, const py::kwargs& keywords) {
    // The render holds its own reference: other Python threads go on meanwhile and may drop
    // or change the Scene.
    const std::shared_ptr<const PreparedScene> prepared = scene.prepared();
    const RenderSettings settings = settings_for(*prepared, keywords, "render");
    Film film(settings.width, settings.height);
    std::optional<AovFilm> aovs;
    if (!settings.aovs.empty()) aovs.emplace(settings.width, settings.height, settings.aovs);
    const std::unique_ptr<Integrator> integrator = make_integrator(settings);
    run_interruptibly(
        [&](const ReportProgress& report, const std::atomic<bool>& stop) {
            integrator->render(prepared->scene, settings, film, report, &stop, nullptr, aovs ? &*aovs : nullptr);
        },
        progress);
    Image image = film.to_image();
    if (aovs) image = aovs->append_to(image);
    if (settings.crop)
        image = crop_of(image, int(settings.crop->x0), int(settings.crop->y0), int(settings.crop->x1),
                        int(settings.crop->y1));
    return {std::move(image), prepared->display};
}

py::object explain(PythonScene& scene, std::pair<int64_t, int64_t> pixel, std::optional<int64_t> sample,
                   const py::kwargs& keywords) {
    const std::shared_ptr<const PreparedScene> prepared = scene.prepared();
    const RenderSettings settings = settings_for(*prepared, keywords, "explain");
    const auto [x, y] = pixel;
    if (x < 0 || y < 0 || x >= settings.width || y >= settings.height)
        throw py::value_error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                              std::to_string(settings.width) + "×" + std::to_string(settings.height) +
                              " image (columns 0 to " + std::to_string(settings.width - 1) + ", rows 0 to " +
                              std::to_string(settings.height - 1) + ")");
    const int64_t spp = int64_t(settings.samples_per_axis) * settings.samples_per_axis;
    if (sample && (*sample < 0 || *sample >= spp))
        throw py::value_error("sample " + std::to_string(*sample) + ": this render takes " + std::to_string(spp) +
                              " samples per pixel, 0 to " + std::to_string(spp - 1));
    const std::unique_ptr<Integrator> integrator = make_integrator(settings);
    std::string json;
    {
        const py::gil_scoped_release release;
        const PixelExplanation explanation =
            integrator->explain(prepared->scene, settings, uint32_t(x), uint32_t(y),
                                sample ? std::optional<uint32_t>(uint32_t(*sample)) : std::nullopt);
        json = explanation_json(prepared->scene, settings, explanation);
    }
    return py::module_::import("json").attr("loads")(json);
}

}  // namespace glint::python
