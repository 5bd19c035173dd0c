#include "explain_command.h"
#include "glint/integrators/explanation_format.h"
#include "thread_limit.h"

#include "glint/integrators/integrator.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/render_scene.h"

#include <fmt/core.h>

#include <charconv>
#include <stdexcept>

namespace glint::app {

namespace {

struct PixelCoordinates {
    uint32_t x = 0, y = 0;
};

/// "X,Y" as two whole numbers.
PixelCoordinates parse_pixel(const std::string& text) {
    const auto comma = text.find(',');
    const auto bad = [&] {
        return std::invalid_argument(
            fmt::format("--pixel: expected X,Y (column and row from the top-left, whole numbers); got '{}'", text));
    };
    if (comma == std::string::npos) throw bad();
    auto number = [&](std::string_view part) {
        uint32_t value = 0;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || error != std::errc() || end != part.data() + part.size()) throw bad();
        return value;
    };
    const std::string_view all(text);
    return {number(all.substr(0, comma)), number(all.substr(comma + 1))};
}

}  // namespace

void add_explain_options(CLI::App* cmd, ExplainOptions& opt) {
    cmd->add_option("scene", opt.scene_path, "Scene file, as for `glint render`; none explains the built-in scene")
        ->check(CLI::ExistingFile);
    cmd->add_option("--pixel", opt.pixel, "The pixel: X,Y (column and row from the top-left)")->required();
    cmd->add_option("--sample", opt.sample, "Show the rays of this sample only (0 to spp − 1; default: every sample)");
    cmd->add_flag("--json", opt.json, "Print JSON for tools instead of an indented tree");
    add_render_overrides(cmd, opt.overrides);
    add_scene_options(cmd, opt.scene);
}

int run_explain(const ExplainOptions& opt) {
    RenderSettings checked;
    apply_overrides(opt.overrides, checked);
    const ThreadLimit thread_limit(checked.threads);
    const PixelCoordinates pixel = parse_pixel(opt.pixel);
    SceneSource source = load_scene(opt.scene_path, opt.scene);
    for (const std::string& w : source.loaded.warnings) fmt::print(stderr, "warning: {}\n", w);
    RenderSettings& s = source.loaded.settings;
    apply_overrides(opt.overrides, s);
    if (pixel.x >= s.width || pixel.y >= s.height)
        throw std::invalid_argument(fmt::format("--pixel {}: outside the {}×{} image (columns 0 to {}, rows 0 to {})",
                                                opt.pixel, s.width, s.height, s.width - 1, s.height - 1));
    const uint32_t spp = s.samples_per_axis * s.samples_per_axis;
    std::optional<uint32_t> sample;
    if (opt.sample)
        sample = in_range("--sample", *opt.sample, 0, int64_t(spp) - 1,
                          fmt::format("a sample of this render's {} per pixel, 0 to {}", spp, spp - 1));

    const RenderScene scene(std::move(source.loaded.scene));
    const std::unique_ptr<Integrator> integrator = make_integrator(s);
    const PixelExplanation explanation = integrator->explain(scene, s, pixel.x, pixel.y, sample);
    if (opt.json)
        fmt::print("{}\n", explanation_json(scene, s, explanation));
    else
        fmt::print("{}", explanation_text(scene, s, explanation));
    return 0;
}

}  // namespace glint::app
