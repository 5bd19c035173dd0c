// glint: the command-line front end of libglint. It parses arguments, loads a scene,
// renders it and writes the image; everything else lives in the library.

#include "info_command.h"
#include "progress_bar.h"
#include "scene_source.h"
#include "timing.h"

#include "glint/image/image_io.h"
#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/render_settings.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_file.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <optional>
#include <unistd.h>

namespace {

using glint::app::Clock;
using glint::app::seconds_since;

struct RenderOptions {
    std::string scene_path;
    glint::app::SceneOptions scene;
    std::string output;
    std::optional<uint32_t> width, height, spp, depth, threads;
    std::optional<uint64_t> seed;
    std::optional<std::string> filter, integrator, mis;
    std::optional<float> filter_radius;
    std::optional<uint32_t> light_samples;
    float exposure = 0.0f;
    bool quiet = false;
};

int run_render(const RenderOptions& opt) {
    const auto load_start = Clock::now();
    glint::app::SceneSource source = glint::app::load_scene(opt.scene_path, opt.scene);
    glint::LoadedScene& loaded = source.loaded;
    auto warn = [&](const std::string& w) {
        if (!opt.quiet) fmt::print(stderr, "warning: {}\n", w);
    };
    for (const std::string& w : loaded.warnings) warn(w);

    glint::RenderSettings& s = loaded.settings;
    if (opt.width) s.width = *opt.width;
    if (opt.height) s.height = *opt.height;
    if (opt.spp) {
        const std::optional<uint32_t> n = glint::samples_per_axis(*opt.spp);
        if (!n)
            throw std::invalid_argument(fmt::format(
                "--spp {} is not a square number: Glint takes N×N stratified samples (1, 4, 9, 16, 25, ...)", *opt.spp));
        s.samples_per_axis = *n;
    }
    if (opt.depth) s.max_depth = *opt.depth;
    if (opt.threads) s.threads = *opt.threads;
    if (opt.seed) s.seed = *opt.seed;
    if (opt.filter) {
        s.filter = *glint::filter_from_name(*opt.filter);  // CLI11 checked the name
        s.filter_radius = 0.0f;                             // a filter named here takes its own default radius
    }
    if (opt.filter_radius) s.filter_radius = *opt.filter_radius;
    if (opt.integrator) s.integrator = *opt.integrator;
    if (opt.light_samples) s.light_samples = *opt.light_samples;
    if (opt.mis) s.mis = *opt.mis == "balance" ? glint::MisHeuristic::Balance : glint::MisHeuristic::Power;
    if (s.width == 0 || s.height == 0) throw std::invalid_argument("image width and height must be at least 1");

    std::string output = opt.output;
    if (output.empty())
        output = opt.scene_path.empty() ? "spheres.png"
                                        : std::filesystem::path(opt.scene_path).stem().string() + ".png";
    if (!glint::is_supported_output(output))
        throw glint::ImageError(output + ": unknown image extension (expected .exr, .hdr, .pfm, .png, .jpg or .tif)");
    const double load_seconds = seconds_since(load_start);

    const auto build_start = Clock::now();
    const glint::RenderScene scene(std::move(loaded.scene));
    const double build_seconds = seconds_since(build_start);

    glint::Film film(s.width, s.height);
    const std::unique_ptr<glint::Integrator> integrator = glint::make_integrator(s);
    for (const std::string& w : integrator->warnings(scene)) warn(w);
    glint::app::ProgressBar bar(!opt.quiet && ::isatty(STDERR_FILENO));
    const glint::RenderStats stats =
        integrator->render(scene, s, film, [&](uint32_t done, uint32_t total) { bar.update(done, total); });
    bar.finish();

    glint::WriteOptions write_options;
    write_options.exposure = opt.exposure;
    glint::write_image(output, film.to_image(), write_options);

    if (opt.quiet) return 0;
    const double mrays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds * 1e-6 : 0.0;
    fmt::print("{}x{}, {} spp: load {:.2f} s, build {:.2f} s, render {:.2f} s, {:.2f} M rays ({:.2f} M rays/s) -> {}\n",
               s.width, s.height, s.samples_per_axis * s.samples_per_axis, load_seconds, build_seconds, stats.seconds,
               double(stats.rays) * 1e-6, mrays_per_second, output);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Glint: a classic Whitted ray tracer"};
    app.require_subcommand(1);

    RenderOptions render;
    CLI::App* render_cmd = app.add_subcommand("render", "Render a scene file (or the built-in spheres scene) to an image");
    render_cmd->add_option("scene", render.scene_path,
                           "Scene file (.toml, .gltf/.glb, or a mesh: .ply/.obj/.stl/.fbx); none renders the built-in scene")
        ->check(CLI::ExistingFile);
    render_cmd->add_option("-o,--output", render.output,
                           "Output image: .exr/.hdr/.pfm (linear) or .png/.jpg/.tif (sRGB); default <scene>.png");
    render_cmd->add_option("--width", render.width, "Image width in pixels")->check(CLI::PositiveNumber);
    render_cmd->add_option("--height", render.height, "Image height in pixels")->check(CLI::PositiveNumber);
    render_cmd->add_option("--spp", render.spp, "Samples per pixel, a square N² (N×N stratified)")
        ->check(CLI::PositiveNumber);
    render_cmd->add_option("--depth", render.depth, "Maximum reflection/refraction depth");
    render_cmd->add_option("--threads", render.threads, "Worker threads (0 = all cores)");
    render_cmd->add_option("--seed", render.seed, "Random seed");
    const std::vector<std::string> filter_names(glint::filter_names().begin(), glint::filter_names().end());
    render_cmd->add_option("--filter", render.filter, "Pixel filter")->check(CLI::IsMember(filter_names));
    render_cmd->add_option("--filter-radius", render.filter_radius, "Pixel filter radius in pixels (default: the filter's)")
        ->check(CLI::Range(0.001f, 16.0f));
    std::vector<std::string> integrator_names;
    for (std::string_view name : glint::integrator_names()) integrator_names.emplace_back(name);
    render_cmd->add_option("--integrator", render.integrator, "Integrator (default: the scene's, else whitted)")
        ->check(CLI::IsMember(integrator_names));
    render_cmd->add_option("--light-samples", render.light_samples, "Whitted: samples per area light per shading point")
        ->check(CLI::Range(1, 1024));
    render_cmd->add_option("--mis", render.mis, "Path: multiple importance sampling heuristic")
        ->check(CLI::IsMember({"balance", "power"}));
    render_cmd->add_option("--exposure", render.exposure, "Exposure in stops for PNG/JPEG/TIFF output");
    render_cmd->add_flag("-q,--quiet", render.quiet, "Print nothing but errors: no progress bar, warnings or summary");
    glint::app::add_scene_options(render_cmd, render.scene);

    std::string info_path;
    glint::app::SceneOptions info_options;
    CLI::App* info_cmd = app.add_subcommand("info", "Print what a scene file holds (and, for glTF, what was mapped)");
    info_cmd->add_option("scene", info_path, "Scene file")->required()->check(CLI::ExistingFile);
    glint::app::add_scene_options(info_cmd, info_options);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    try {
        if (*render_cmd) return run_render(render);
        if (*info_cmd) return glint::app::run_info(info_path, info_options);
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return 1;
    }
    return 0;
}
