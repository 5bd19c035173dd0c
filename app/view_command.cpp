#include "view_command.h"

#include "display_options.h"
#include "program_beside.h"
#include "thread_limit.h"

#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/render_scene.h"

#ifdef GLINT_HAVE_VIEWER
#include "viewer/session_script.h"
#include "viewer/viewer_window.h"
#endif

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace glint::app {

void add_view_options(CLI::App* cmd, ViewOptions& opt) {
    cmd->add_option("scene", opt.scene_path, "Scene file, as for `glint render`; none shows the built-in scene")
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", opt.output, "Where S saves the image (.exr linear, .png sRGB); default <scene>.png");
    add_display_options(cmd, opt.exposure, opt.tone_curve);
    cmd->add_option("--script", opt.script, "Run a scripted session from this file (for tests and demos)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--benchmark", opt.benchmark,
                    "Orbit for N frames, then render to convergence; print frames/s and the time, and close");
    add_render_overrides(cmd, opt.overrides);
    add_scene_options(cmd, opt.scene);
}

int run_view(const ViewOptions& opt, int argc, char** argv) {
#if !defined(GLINT_HAVE_VIEWER) && defined(GLINT_VIEWER_PROGRAM)
    // The viewer's program takes over this process with the same arguments, so that only
    // `glint view` loads the viewer's libraries.
    (void)opt;
    throw std::runtime_error(run_program_beside(GLINT_VIEWER_PROGRAM, argc, argv) +
                             " (the viewer: build it again, it is built with glint)");
#elif !defined(GLINT_HAVE_VIEWER)
    (void)opt;
    (void)argc;
    (void)argv;
    throw std::runtime_error(
        "this glint was built without the viewer (SDL2 or Dear ImGui was missing, or GLINT_VIEWER=OFF): install "
        "libsdl2-dev and libimgui-dev (scripts/setup.sh does) and build again");
#else
    (void)argc;
    (void)argv;
    RenderSettings checked;
    apply_overrides(opt.overrides, checked);
    const ThreadLimit thread_limit(checked.threads);
    std::string output = opt.output;
    if (output.empty())
        output =
            opt.scene_path.empty() ? "spheres.png" : std::filesystem::path(opt.scene_path).stem().string() + ".png";
    check_output_path(output);
    const int benchmark =
        opt.benchmark ? int(in_range("--benchmark", *opt.benchmark, 1, 100000, "a frame count from 1 to 100000")) : 0;
    std::vector<ScriptStep> script;
    if (opt.script) {
        std::ifstream in(*opt.script);
        script = parse_session_script({std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()});
    }
    SceneSource source = load_scene(opt.scene_path, opt.scene);
    for (const std::string& w : source.loaded.warnings) fmt::print(stderr, "warning: {}\n", w);
    RenderSettings& s = source.loaded.settings;
    apply_overrides(opt.overrides, s);
    const RenderScene scene(std::move(source.loaded.scene));
    const std::unique_ptr<Integrator> integrator = make_integrator(s);
    ViewerWindow window(scene, *integrator, s, ViewerOptions{output, with_display_options(source.loaded.display, opt.exposure, opt.tone_curve),
                                                                      std::move(script), benchmark});
    return window.run();
#endif
}

}  // namespace glint::app
