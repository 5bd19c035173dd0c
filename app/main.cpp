// glint: the command-line front end of libglint. It parses arguments, loads a scene,
// renders it and writes the image; everything else lives in the library.

#include "assemble_command.h"
#include "display_options.h"
#include "explain_command.h"
#include "info_command.h"
#include "mpi_session.h"
#include "render_command.h"
#include "scene_source.h"
#include "view_command.h"

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // No fastbins: loading a large scene frees millions of small blocks (toml++'s tree and
    // the scene tables), which glibc otherwise merges later in bursts (malloc_consolidate
    // and unlink_chunk were 10 % of a 100,000-instance load). That load: 1.90 -> 1.59 s; the
    // example scenes and mesh files within ±2 % (docs/performance.md, "100,000 instances").
    mallopt(M_MXFAST, 0);
#endif
    // Under mpirun every rank runs this program with the same arguments (mpi_session.h).
    const glint::app::MpiSession mpi(argc, argv);
    CLI::App app{"Glint: a classic Whitted ray tracer"};
    app.require_subcommand(1);

    glint::app::RenderOptions render;
    render.mpi = &mpi;
    CLI::App* render_cmd =
        app.add_subcommand("render", "Render a scene file (or the built-in spheres scene) to an image");
    render_cmd
        ->add_option("scene", render.scene_path,
                     "Scene file (.toml, .gltf/.glb, or a mesh: .ply/.obj/.stl/.fbx); none renders the built-in scene")
        ->check(CLI::ExistingFile);
    render_cmd->add_option("-o,--output", render.output,
                           "Output image: .exr/.hdr/.pfm (linear) or .png/.jpg/.tif (sRGB); default <scene>.png");
    glint::app::add_render_overrides(render_cmd, render.overrides);
    render_cmd->add_option("--crop", render.overrides.crop,
                           "Render only the region X0,Y0,X1,Y1: pixels [X0, X1) × [Y0, Y1) from the top left, or "
                           "fractions of the image (0.5,0,1,0.5: the top-right quarter); an EXR keeps its place in the "
                           "frame for `glint assemble`");
    glint::app::add_display_options(render_cmd, render.exposure, render.tone_curve);
    render_cmd->add_flag("--resume", render.resume,
                         "Continue an interrupted render from the checkpoint beside the output (<output>.checkpoint)");
    render_cmd->add_option("--checkpoint-every", render.checkpoint_every,
                           "Save a checkpoint beside the output every SECONDS while rendering");
    render_cmd->add_option("--display-server", render.display_server,
                           "Show the image as it renders in an HDR viewer speaking tev's protocol, at HOST:PORT "
                           "(tev listens on 127.0.0.1:14158)");
    CLI::Option* frames = render_cmd->add_option(
        "--frames", render.frames,
        "Render an animation: frames FIRST-LAST, FIRST-LAST:STEP or N, comma-separated; -o names "
        "them with a run of # (out_####.exr); frames already there are skipped");
    render_cmd->add_option("--fps", render.fps, "With --frames: frames per second; frame F shows scene time F / fps")
        ->capture_default_str()
        ->needs(frames);
    render_cmd
        ->add_option("--motion-blur", render.motion_blur,
                     "With --frames: the fraction of a frame (0 to 1) the shutter stays open from its time")
        ->capture_default_str()
        ->needs(frames);
    render_cmd->add_flag("--overwrite", render.overwrite, "With --frames: render frames already there again")
        ->needs(frames);
    render_cmd->add_flag("-q,--quiet", render.quiet, "Print nothing but errors: no progress bar, warnings or summary");
    glint::app::add_scene_options(render_cmd, render.scene);

    std::string info_path;
    glint::app::SceneOptions info_options;
    CLI::App* info_cmd = app.add_subcommand("info", "Print what a scene file holds (and, for glTF, what was mapped)");
    info_cmd->add_option("scene", info_path, "Scene file")->required()->check(CLI::ExistingFile);
    glint::app::add_scene_options(info_cmd, info_options);

    glint::app::AssembleOptions assemble;
    CLI::App* assemble_cmd = app.add_subcommand(
        "assemble", "Join the crops of one render (glint render --crop, EXR) into the frame they make");
    glint::app::add_assemble_options(assemble_cmd, assemble);

    glint::app::ExplainOptions explain;
    CLI::App* explain_cmd = app.add_subcommand(
        "explain", "Why a pixel has its colour: the rays of its samples, what they hit and what each adds");
    glint::app::add_explain_options(explain_cmd, explain);

    glint::app::ViewOptions view;
    CLI::App* view_cmd = app.add_subcommand(
        "view", "Open a window that renders the scene progressively, with an orbit camera and pixel explanations");
    glint::app::add_view_options(view_cmd, view);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help is no error; every mistake exits with 1, as errors found later do.
        const int status = app.exit(e) == 0 ? 0 : 1;
        // Under mpirun, one rank's mistake ends every rank rather than leaving them waiting.
        if (status != 0 && mpi.distributed()) mpi.abort("the command line above is refused");
        return status;
    }

    int status = 0;
    try {
        if (*render_cmd) status = glint::app::run_render(render);
        if (*info_cmd) status = glint::app::run_info(info_path, info_options);
        if (*assemble_cmd) status = glint::app::run_assemble(assemble);
        if (*explain_cmd) status = glint::app::run_explain(explain);
        if (*view_cmd) status = glint::app::run_view(view, argc, argv);
    } catch (const std::exception& e) {
        if (mpi.distributed()) mpi.abort(e.what());
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return 1;
    }
    if (status != 0 && mpi.distributed()) mpi.abort(fmt::format("stopped with exit status {}", status));
    return status;
}
