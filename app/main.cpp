// glint: the command-line front end of libglint. It parses arguments, loads a scene,
// renders it and writes the image; everything else lives in the library.

#include "progress_bar.h"

#include "glint/image/image_io.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/io/environment.h"
#include "glint/io/gltf_scene_loader.h"
#include "glint/io/scene_file.h"
#include "glint/scene/default_scene.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <unistd.h>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// How to pick the scene's camera and environment; shared by `render` and `info`.
struct SceneOptions {
    std::string camera;
    std::string env;
    std::string env_kind;
    float env_rotation = 0.0f;
    float env_intensity = 1.0f;
};

struct RenderOptions {
    std::string scene_path;
    SceneOptions scene;
    std::string output;
    std::optional<uint32_t> width, height, spp, depth, threads;
    std::optional<uint64_t> seed;
    std::optional<std::string> filter;
    float exposure = 0.0f;
    bool quiet = false;
};

/// Samples per pixel must be N² for N×N stratification.
uint32_t samples_per_axis(uint32_t spp) {
    const auto n = static_cast<uint32_t>(std::lround(std::sqrt(double(spp))));
    if (spp == 0 || n * n != spp)
        throw std::invalid_argument(fmt::format(
            "--spp {} is not a square number: Glint takes N×N stratified samples (1, 4, 9, 16, 25, ...)", spp));
    return n;
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

/// A loaded scene and, for glTF files, what the loader mapped.
struct SceneSource {
    glint::LoadedScene loaded;
    std::optional<glint::GltfReport> gltf;
    /// The scene is lit by the asset default lighting (no lights in the file).
    bool default_lighting = false;
};

SceneSource load_scene(const std::string& path, const SceneOptions& opt) {
    SceneSource source;
    const std::string ext = lower_extension(path);
    if (path.empty()) {
        source.loaded.scene = glint::make_spheres_scene();
        source.loaded.settings.samples_per_axis = 2;
    } else if (ext == ".gltf" || ext == ".glb") {
        glint::GltfScene gltf = glint::load_gltf_scene(path, glint::GltfOptions{opt.camera});
        source.loaded = std::move(gltf.loaded);
        source.default_lighting = gltf.report.default_lighting;
        source.gltf = std::move(gltf.report);
    } else {
        source.loaded = glint::load_scene_file(path);
        source.default_lighting = ext != ".toml";  // bare mesh files get the default lighting
    }
    if (!opt.camera.empty() && !source.gltf)
        throw std::invalid_argument("--camera picks a camera of a glTF file; " +
                                    (path.empty() ? std::string("the built-in scene") : path) + " is not one");
    if (!opt.env.empty()) {
        glint::EnvironmentOptions env;
        if (!opt.env_kind.empty()) env.kind = glint::parse_environment_kind(opt.env_kind);
        env.rotation_degrees = opt.env_rotation;
        env.intensity = opt.env_intensity;
        glint::Scene& scene = source.loaded.scene;
        scene.background = glint::load_environment(opt.env, env);
        // Under the default lighting the environment also replaces the grey ambient sky.
        if (source.default_lighting) scene.ambient_light = glint::average_radiance(scene.background);
    }
    return source;
}

int run_render(const RenderOptions& opt) {
    const auto load_start = Clock::now();
    SceneSource source = load_scene(opt.scene_path, opt.scene);
    glint::LoadedScene& loaded = source.loaded;
    for (const std::string& w : loaded.warnings) fmt::print(stderr, "warning: {}\n", w);

    glint::RenderSettings& s = loaded.settings;
    if (opt.width) s.width = *opt.width;
    if (opt.height) s.height = *opt.height;
    if (opt.spp) s.samples_per_axis = samples_per_axis(*opt.spp);
    if (opt.depth) s.max_depth = *opt.depth;
    if (opt.threads) s.threads = *opt.threads;
    if (opt.seed) s.seed = *opt.seed;
    if (opt.filter) s.filter = *opt.filter == "tent" ? glint::PixelFilter::Tent : glint::PixelFilter::Box;
    if (s.width == 0 || s.height == 0) throw std::invalid_argument("image width and height must be at least 1");

    std::string output = opt.output;
    if (output.empty())
        output = opt.scene_path.empty() ? "spheres.png"
                                        : std::filesystem::path(opt.scene_path).stem().string() + ".png";
    if (!glint::is_supported_output(output))
        throw glint::ImageError(output + ": unknown image extension (expected .exr, .hdr, .pfm, .png, .jpg or .tif)");
    const double load_seconds = seconds_since(load_start);

    const auto build_start = Clock::now();
    loaded.scene.prepare();
    const double build_seconds = seconds_since(build_start);

    glint::Film film(s.width, s.height);
    glint::WhittedIntegrator integrator(s.max_depth);
    glint::app::ProgressBar bar(!opt.quiet && ::isatty(STDERR_FILENO));
    const glint::RenderStats stats =
        integrator.render(loaded.scene, s, film, [&](uint32_t done, uint32_t total) { bar.update(done, total); });
    bar.finish();

    glint::WriteOptions write_options;
    write_options.exposure = opt.exposure;
    glint::write_image(output, film.to_image(), write_options);

    const double mrays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds * 1e-6 : 0.0;
    fmt::print("{}x{}, {} spp: load {:.2f} s, build {:.2f} s, render {:.2f} s, {:.2f} M rays ({:.2f} M rays/s) -> {}\n",
               s.width, s.height, s.samples_per_axis * s.samples_per_axis, load_seconds, build_seconds, stats.seconds,
               double(stats.rays) * 1e-6, mrays_per_second, output);
    return 0;
}

std::string megabytes(std::size_t bytes) { return fmt::format("{:.1f} MB", double(bytes) / (1024.0 * 1024.0)); }

/// `glint info`: what a scene holds, and for glTF what was mapped and ignored.
int run_info(const std::string& path, const SceneOptions& opt) {
    const auto load_start = Clock::now();
    SceneSource source = load_scene(path, opt);
    const double load_seconds = seconds_since(load_start);
    glint::Scene& scene = source.loaded.scene;
    const auto build_start = Clock::now();
    scene.prepare();
    const double build_seconds = seconds_since(build_start);
    const glint::SceneStatistics stats = scene.statistics();

    std::map<std::string, int> light_kinds;
    for (const auto& light : scene.lights()) ++light_kinds[std::string(light->type_name())];
    std::string lights;
    for (const auto& [kind, count] : light_kinds) lights += fmt::format("{}{} {}", lights.empty() ? "" : ", ", count, kind);

    fmt::print("file:        {}\n", path);
    fmt::print("objects:     {} ({} unique shapes)\n", stats.objects, stats.unique_shapes);
    fmt::print("triangles:   {} unique, {} instanced\n", stats.unique_triangles, stats.instanced_triangles);
    fmt::print("materials:   {}\n", scene.materials().size());
    fmt::print("textures:    {}\n", scene.texture_count());
    fmt::print("lights:      {}{}{}\n", scene.lights().size(), lights.empty() ? "" : ": ", lights);
    if (source.gltf) {
        const glint::GltfReport& r = *source.gltf;
        fmt::print("cameras:     {} in the file\n", r.cameras.size());
        for (std::size_t i = 0; i < r.cameras.size(); ++i) {
            const glint::GltfCamera& c = r.cameras[i];
            const glint::Camera& cam = c.camera;
            fmt::print("  {} #{} '{}' {} at ({:.4g}, {:.4g}, {:.4g}){}\n", int(i) == r.selected_camera ? "*" : " ",
                       c.index, c.name,
                       cam.projection() == glint::Projection::Perspective
                           ? fmt::format("perspective yfov {:.4g} deg", cam.vertical_fov())
                           : fmt::format("orthographic height {:.4g}", cam.view_height()),
                       cam.eye().x, cam.eye().y, cam.eye().z,
                       c.aspect > 0.0f ? fmt::format(", aspect {:.4g}", c.aspect) : std::string());
        }
    }
    const glint::Camera& cam = scene.camera;
    fmt::print("camera:      {} at ({:.4g}, {:.4g}, {:.4g}) looking ({:.3f}, {:.3f}, {:.3f})\n",
               cam.projection() == glint::Projection::Perspective
                   ? fmt::format("perspective {:.4g} deg", cam.vertical_fov())
                   : fmt::format("orthographic {:.4g}", cam.view_height()),
               cam.eye().x, cam.eye().y, cam.eye().z, cam.forward().x, cam.forward().y, cam.forward().z);
    const glint::Bounds3 b = scene.bounds();
    fmt::print("bounds:      ({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g})\n", b.lo.x, b.lo.y, b.lo.z, b.hi.x,
               b.hi.y, b.hi.z);
    fmt::print("memory:      {} (geometry + acceleration structures)\n", megabytes(stats.memory_bytes));
    fmt::print("image:       {}x{}\n", source.loaded.settings.width, source.loaded.settings.height);
    if (source.gltf) {
        const glint::GltfReport& r = *source.gltf;
        fmt::print("glTF:        {} mesh(es), {} primitive(s), {} light(s), {} material(s)\n", r.meshes, r.primitives,
                   r.lights, r.materials);
        fmt::print("mapped:\n");
        for (const std::string& line : r.mapped) fmt::print("  {}\n", line);
        fmt::print("ignored:{}\n", r.ignored.empty() ? " nothing" : "");
        for (const std::string& line : r.ignored) fmt::print("  {}\n", line);
    } else {
        for (const std::string& w : source.loaded.warnings) fmt::print("warning:     {}\n", w);
    }
    fmt::print("load {:.2f} s, build {:.2f} s\n", load_seconds, build_seconds);
    return 0;
}

/// The flags that choose a camera and an environment, on both subcommands.
void add_scene_options(CLI::App* cmd, SceneOptions& opt) {
    cmd->add_option("--camera", opt.camera, "glTF camera to render through: name or index (default: the first)");
    cmd->add_option("--env", opt.env, "HDR environment map (background and reflections)")->check(CLI::ExistingFile);
    cmd->add_option("--env-kind", opt.env_kind, "Environment layout (default: 2:1 equirect, 1:1 spheremap)")
        ->check(CLI::IsMember({"equirect", "spheremap"}));
    cmd->add_option("--env-rotation", opt.env_rotation, "Environment rotation about +y in degrees");
    cmd->add_option("--env-intensity", opt.env_intensity, "Environment radiance scale")->check(CLI::NonNegativeNumber);
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
    render_cmd->add_option("--filter", render.filter, "Pixel filter")->check(CLI::IsMember({"box", "tent"}));
    render_cmd->add_option("--exposure", render.exposure, "Exposure in stops for PNG/JPEG/TIFF output");
    render_cmd->add_flag("-q,--quiet", render.quiet, "No progress bar");
    add_scene_options(render_cmd, render.scene);

    std::string info_path;
    SceneOptions info_options;
    CLI::App* info_cmd = app.add_subcommand("info", "Print what a scene file holds (and, for glTF, what was mapped)");
    info_cmd->add_option("scene", info_path, "Scene file")->required()->check(CLI::ExistingFile);
    add_scene_options(info_cmd, info_options);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    try {
        if (*render_cmd) return run_render(render);
        if (*info_cmd) return run_info(info_path, info_options);
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint: error: {}\n", e.what());
        return 1;
    }
    return 0;
}
