// glint: the command-line front end of libglint. It parses arguments, loads a scene,
// renders it and writes the image; everything else lives in the library.

#include "info_command.h"
#include "render_command.h"
#include "scene_source.h"

#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <string>
#include <vector>

int main(int argc, char** argv) {
    CLI::App app{"Glint: a classic Whitted ray tracer"};
    app.require_subcommand(1);

    glint::app::RenderOptions render;
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
    render_cmd->add_flag("--resume", render.resume,
                         "Continue an interrupted render from the checkpoint beside the output (<output>.checkpoint)");
    render_cmd->add_option("--checkpoint-every", render.checkpoint_every,
                           "Save a checkpoint beside the output every SECONDS while rendering");
    render_cmd->add_option("--display-server", render.display_server,
                           "Show the image as it renders in an HDR viewer speaking tev's protocol, at HOST:PORT "
                           "(tev listens on 127.0.0.1:14158)");
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
        if (*render_cmd) return glint::app::run_render(render);
        if (*info_cmd) return glint::app::run_info(info_path, info_options);
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return 1;
    }
    return 0;
}
