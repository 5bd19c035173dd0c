/// glint-scene-bench: whole renders, end to end, as `glint render` runs them (load the file,
/// build the render scene, render), at fixed settings, so that every change can be compared
/// on the scenes users render. Prints per scene the time to first pixel (load + build), the
/// render time, rays traced and rays per second, as a table or as JSON.

#include "glint/image/film.h"
#include "glint/integrators/integrator.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_file.h"

#include <fmt/core.h>
#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// One scene's run.
struct Record {
    std::string scene;
    std::string integrator;
    uint32_t spp = 1;
    double load = 0.0, build = 0.0, render = 0.0;
    uint64_t rays = 0;
    [[nodiscard]] double first_pixel() const { return load + build; }
    [[nodiscard]] double total() const { return load + build + render; }
    [[nodiscard]] double mrays_per_second() const { return render > 0.0 ? double(rays) / render * 1e-6 : 0.0; }
};

struct Settings {
    uint32_t width = 640, height = 480, threads = 2;
    std::optional<uint32_t> spp;
};

/// Load, build and render `path` as `glint render` does, timing each step.
Record run(const fs::path& path, const Settings& settings) {
    Record r;
    r.scene = path.stem().string();
    const auto load_start = Clock::now();
    glint::LoadedScene loaded = glint::load_scene_file(path).loaded;
    glint::RenderSettings& s = loaded.settings;
    s.width = settings.width;
    s.height = settings.height;
    s.threads = settings.threads;
    if (settings.spp) {
        const std::optional<uint32_t> n = glint::samples_per_axis(*settings.spp);
        if (!n) throw std::invalid_argument("--spp must be a square number");
        s.samples_per_axis = *n;
    }
    r.load = seconds_since(load_start);
    const auto build_start = Clock::now();
    const glint::RenderScene scene(std::move(loaded.scene));
    r.build = seconds_since(build_start);
    glint::Film film(s.width, s.height);
    const glint::RenderStats stats = glint::make_integrator(s)->render(scene, s, film, {});
    r.render = stats.seconds;
    r.rays = stats.rays;
    r.integrator = s.integrator;
    r.spp = s.samples_per_axis * s.samples_per_axis;
    return r;
}

/// Every scenes/*.toml, then the shared Stanford meshes that exist (bare mesh files rendered
/// as scenes: framing camera, default lighting).
std::vector<fs::path> default_scenes() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(fs::path(GLINT_SOURCE_DIR) / "scenes"))
        if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    for (const char* mesh : {"stanford_bunny.ply", "stanford_lucy_100k.ply", "stanford_dragon.ply"})
        if (const fs::path p = fs::path(GLINT_SHARED_DATA_DIR) / "meshes" / mesh; fs::exists(p)) scenes.push_back(p);
    return scenes;
}

void print_table(const std::vector<Record>& records, const Settings& settings) {
    fmt::print("{}x{}, {} thread(s); times in seconds\n\n", settings.width, settings.height, settings.threads);
    fmt::print("| scene | integrator | spp | load | build | first pixel | render | total | M rays | M rays/s |\n");
    fmt::print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Record& r : records)
        fmt::print("| {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.2f} | {:.2f} |\n", r.scene,
                   r.integrator, r.spp, r.load, r.build, r.first_pixel(), r.render, r.total(), double(r.rays) * 1e-6,
                   r.mrays_per_second());
}

void print_json(const std::vector<Record>& records, const Settings& settings) {
    fmt::print("[\n");
    for (std::size_t i = 0; i < records.size(); ++i) {
        const Record& r = records[i];
        fmt::print(
            "{{\"scene\": \"{}\", \"integrator\": \"{}\", \"width\": {}, \"height\": {}, \"spp\": {}, \"threads\": {}, "
            "\"load_s\": {:.4f}, \"build_s\": {:.4f}, \"first_pixel_s\": {:.4f}, \"render_s\": {:.4f}, "
            "\"total_s\": {:.4f}, \"rays\": {}, \"mrays_per_s\": {:.4f}}}{}\n",
            r.scene, r.integrator, settings.width, settings.height, r.spp, settings.threads, r.load, r.build,
            r.first_pixel(), r.render, r.total(), r.rays, r.mrays_per_second(), i + 1 < records.size() ? "," : "");
    }
    fmt::print("]\n");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"glint-scene-bench: whole renders (load, build, render) of every example scene at fixed settings"};
    std::vector<std::string> scene_args;
    Settings settings;
    uint32_t spp = 0;
    bool json = false;
    app.add_option("--scene", scene_args, "Scene files (default: scenes/*.toml and the shared Stanford meshes)")
        ->check(CLI::ExistingFile);
    app.add_option("--width", settings.width, "Image width (default 640)")->check(CLI::Range(1, 16384));
    app.add_option("--height", settings.height, "Image height (default 480)")->check(CLI::Range(1, 16384));
    app.add_option("--threads", settings.threads, "Threads for the whole run: load, build and render (default 2)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--spp", spp, "Samples per pixel for every scene (default: each scene's own)")
        ->check(CLI::Range(1, 4096));
    app.add_flag("--json", json, "Print one JSON array of records instead of the table");
    CLI11_PARSE(app, argc, argv);
    if (spp > 0) settings.spp = spp;
    // Every oneTBB pool, the build's too, so that time to first pixel is measured on the
    // threads the table's header names.
    const tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism, settings.threads);

    std::vector<fs::path> scenes(scene_args.begin(), scene_args.end());
    if (scenes.empty()) scenes = default_scenes();
    std::vector<Record> records;
    try {
        for (const fs::path& path : scenes) {
            if (!json) fmt::print(stderr, "{} ...\n", path.filename().string());
            records.push_back(run(path, settings));
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint-scene-bench: {}\n", e.what());
        return 1;
    }
    if (json)
        print_json(records, settings);
    else
        print_table(records, settings);
    return 0;
}
