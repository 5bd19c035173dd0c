// glint: the command-line front end of libglint. It parses arguments, loads a scene,
// renders it and writes the image; everything else lives in the library.

#include "info_command.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "scene_source.h"
#include "timing.h"

#include "glint/image/image_io.h"
#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/render_settings.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_file.h"
#include "glint/util/file_extension.h"

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
    // Numbers are read signed and wide, then checked against the limits scene files have,
    // so that "-4" or "100000" gets a message in words rather than a conversion error.
    std::optional<int64_t> width, height, spp, depth, threads, seed, light_samples;
    std::optional<std::string> filter, integrator, mis;
    std::optional<double> filter_radius;
    float exposure = 0.0f;
    bool quiet = false;
};

/// `value` of option `name` if it lies in [lo, hi]; otherwise throws "name: expected ...; got value".
uint32_t in_range(std::string_view name, int64_t value, int64_t lo, int64_t hi, std::string_view expected = {}) {
    if (value < lo || value > hi)
        throw std::invalid_argument(fmt::format("{}: expected {}; got {}", name,
                                                expected.empty() ? fmt::format("an integer from {} to {}", lo, hi)
                                                                 : std::string(expected),
                                                value));
    return static_cast<uint32_t>(value);
}

/// The command line's overrides, checked before anything is loaded.
void apply_overrides(const RenderOptions& opt, glint::RenderSettings& s) {
    using Limits = glint::SettingLimits;
    if (opt.width) s.width = in_range("--width", *opt.width, 1, Limits::kMaxImageSide);
    if (opt.height) s.height = in_range("--height", *opt.height, 1, Limits::kMaxImageSide);
    if (opt.spp) {
        const std::string expected =
            fmt::format("a square number 1, 4, 9, ... up to {} (N×N stratified samples)", Limits::kMaxSpp);
        const std::optional<uint32_t> n = glint::samples_per_axis(in_range("--spp", *opt.spp, 1, Limits::kMaxSpp, expected));
        if (!n) throw std::invalid_argument(fmt::format("--spp: expected {}; got {}", expected, *opt.spp));
        s.samples_per_axis = *n;
    }
    if (opt.depth) s.max_depth = in_range("--depth", *opt.depth, 0, Limits::kMaxDepth);
    if (opt.threads)
        s.threads = in_range("--threads", *opt.threads, 0, Limits::kMaxThreads,
                             fmt::format("0 (all cores) or a thread count up to {}", Limits::kMaxThreads));
    if (opt.seed) {
        if (*opt.seed < 0) throw std::invalid_argument(fmt::format("--seed: expected a non-negative integer; got {}", *opt.seed));
        s.seed = static_cast<uint64_t>(*opt.seed);
    }
    if (opt.filter) {
        s.filter = *glint::filter_from_name(*opt.filter);  // CLI11 checked the name
        s.filter_radius = 0.0f;                             // a filter named here takes its own default radius
    }
    if (opt.filter_radius) {
        if (!(*opt.filter_radius > 0.0 && *opt.filter_radius <= Limits::kMaxFilterRadius))
            throw std::invalid_argument(fmt::format("--filter-radius: expected a radius in pixels above 0 and at most {}; got {}",
                                                    Limits::kMaxFilterRadius, *opt.filter_radius));
        s.filter_radius = static_cast<float>(*opt.filter_radius);
    }
    if (opt.integrator) s.integrator = *opt.integrator;
    if (opt.light_samples) s.light_samples = in_range("--light-samples", *opt.light_samples, 1, Limits::kMaxLightSamples);
    if (opt.mis) s.mis = *opt.mis == "balance" ? glint::MisHeuristic::Balance : glint::MisHeuristic::Power;
}

/// Refuse an image whose film and output copies would not fit in the machine's memory,
/// before allocating any of it.
void check_memory(const glint::RenderSettings& s) {
    const double pixels = double(s.width) * double(s.height);
    // The film (Σw·L and Σw), the image it becomes, and the writer's encoded copy.
    const double needed = pixels * (sizeof(glint::Color) + sizeof(float) + 2 * 3 * sizeof(float));
    const double available = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
    if (available > 0.0 && needed > available)
        throw std::invalid_argument(fmt::format("a {}×{} image needs about {:.1f} GB for its film and output, but this "
                                                "machine has {:.1f} GB of memory",
                                                s.width, s.height, needed / 1e9, available / 1e9));
}

int run_render(const RenderOptions& opt) {
    // Every mistake on the command line is reported before the scene is loaded.
    glint::RenderSettings checked;
    apply_overrides(opt, checked);
    std::string output = opt.output;
    if (output.empty())
        output = opt.scene_path.empty() ? "spheres.png" : std::filesystem::path(opt.scene_path).stem().string() + ".png";
    glint::check_output_path(output);

    const auto load_start = Clock::now();
    glint::app::SceneSource source = glint::app::load_scene(opt.scene_path, opt.scene);
    glint::LoadedScene& loaded = source.loaded;
    auto warn = [&](const std::string& w) {
        if (!opt.quiet) fmt::print(stderr, "warning: {}\n", w);
    };
    for (const std::string& w : loaded.warnings) warn(w);

    glint::RenderSettings& s = loaded.settings;
    apply_overrides(opt, s);
    check_memory(s);
    const double load_seconds = seconds_since(load_start);

    const auto build_start = Clock::now();
    const glint::RenderScene scene(std::move(loaded.scene));
    const double build_seconds = seconds_since(build_start);

    glint::Film film(s.width, s.height);
    const std::unique_ptr<glint::Integrator> integrator = glint::make_integrator(s);
    for (const std::string& w : integrator->warnings(scene)) warn(w);
    if (s.threads > glint::max_render_threads())
        warn(fmt::format("--threads {}: this machine runs {} threads at once; rendering with {}", s.threads,
                         glint::max_render_threads(), glint::max_render_threads()));
    glint::app::ProgressBar bar(!opt.quiet && ::isatty(STDERR_FILENO));
    const glint::app::InterruptGuard interrupt(output);
    const glint::RenderStats stats = integrator->render(
        scene, s, film, [&](uint32_t done, uint32_t total) { bar.update(done, total); }, &interrupt.stop());
    bar.finish();

    glint::WriteOptions write_options;
    write_options.exposure = opt.exposure;
    if (!stats.complete()) {
        // Interrupted: keep what is rendered. EXR says per pixel how many samples it has
        // (0 where no tile reached); other formats show unrendered pixels black.
        write_options.fourth_channel = "samples";
        glint::write_image(output, film.to_image(true), write_options);
        fmt::print(stderr, "interrupted: wrote the {} of {} tiles rendered to {}{}\n", stats.tiles_done, stats.tiles,
                   output, glint::lower_case_extension(output) == ".exr" ? " (channel 'samples': samples per pixel)" : "");
        return 128 + interrupt.signal();
    }
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
    render_cmd->add_option("--width", render.width, "Image width in pixels (1 to 16384)");
    render_cmd->add_option("--height", render.height, "Image height in pixels (1 to 16384)");
    render_cmd->add_option("--spp", render.spp, "Samples per pixel, a square N² (N×N stratified), up to 4096");
    render_cmd->add_option("--depth", render.depth, "Maximum reflection/refraction depth (0 to 64)");
    render_cmd->add_option("--threads", render.threads, "Worker threads (0 = all cores)");
    render_cmd->add_option("--seed", render.seed, "Random seed (a non-negative integer)");
    const std::vector<std::string> filter_names(glint::filter_names().begin(), glint::filter_names().end());
    render_cmd->add_option("--filter", render.filter, "Pixel filter")->check(CLI::IsMember(filter_names));
    render_cmd->add_option("--filter-radius", render.filter_radius,
                           "Pixel filter radius in pixels, above 0 and at most 16 (default: the filter's)");
    std::vector<std::string> integrator_names;
    for (std::string_view name : glint::integrator_names()) integrator_names.emplace_back(name);
    render_cmd->add_option("--integrator", render.integrator, "Integrator (default: the scene's, else whitted)")
        ->check(CLI::IsMember(integrator_names));
    render_cmd->add_option("--light-samples", render.light_samples,
                           "Whitted: samples per area light per shading point (1 to 1024)");
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
        // --help is no error; every mistake exits with 1, as errors found later do.
        return app.exit(e) == 0 ? 0 : 1;
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
