#include "render_command.h"

#include "display_options.h"
#include "frame_sequence.h"
#include "interrupt.h"
#include "mpi_session.h"
#include "progress_bar.h"
#include "render_overrides.h"
#include "thread_limit.h"
#include "timing.h"

#include "glint/image/filter.h"
#include "glint/image/frame_assembly.h"
#include "glint/image/image_io.h"
#include "glint/integrators/checkpoint.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/integrators/render_settings.h"
#include "glint/io/film_stream.h"
#include "glint/scene/render_scene.h"
#include "glint/util/file_extension.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <unistd.h>
#include <filesystem>
#include <future>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace glint::app {

namespace {

/// Refuse an image whose film and output copies would not fit in the machine's memory,
/// before allocating any of it.
void check_memory(const glint::RenderSettings& s) {
    const double pixels = double(s.width) * double(s.height);
    // The film (Σw·L and Σw), the image it becomes, and the writer's encoded copy; with
    // AOVs, their film and channels (at most 14) in both copies.
    const double aov_bytes = s.aovs.empty() ? 0.0 : double(sizeof(glint::AovPixel)) + 2 * 14 * sizeof(float);
    const double needed = pixels * (double(sizeof(glint::FilmPixel)) + 2 * 3 * sizeof(float) + aov_bytes);
    const double available = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
    if (available > 0.0 && needed > available)
        throw std::invalid_argument(
            fmt::format("a {}×{} image needs about {:.1f} GB for its film and output, but this "
                        "machine has {:.1f} GB of memory",
                        s.width, s.height, needed / 1e9, available / 1e9));
}

/// The --display-server address, checked like every option before anything is loaded.
std::optional<glint::DisplayAddress> display_address(const RenderOptions& opt) {
    if (!opt.display_server) return std::nullopt;
    try {
        return glint::parse_display_address(*opt.display_server);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--display-server: ") + e.what());
    }
}

/// AOVs are extra channels of an EXR: refuse any other output before rendering.
void check_aov_output(const glint::RenderSettings& s, const std::string& output) {
    if (s.aovs.empty() || glint::lower_case_extension(output) == ".exr") return;
    std::vector<std::string_view> names;
    for (const glint::Aov aov : s.aovs) names.push_back(glint::aov_name(aov));
    throw std::invalid_argument(fmt::format(
        "{}: AOVs ({}) are written as extra channels of an EXR image, which {} cannot hold; expected -o NAME.exr",
        output, fmt::join(names, ", "), glint::lower_case_extension(output)));
}

/// Stopped while loading or building, before a pixel was rendered: an empty image would only
/// replace what the output (or a checkpoint to resume) held before.
int stopped_before_rendering(const InterruptGuard& interrupt) {
    fmt::print(stderr, "interrupted while loading: nothing was rendered, nothing written\n");
    return 128 + interrupt.signal();
}

}  // namespace

int run_render(const RenderOptions& opt) { return opt.frames ? render_frames(opt) : render_image(opt); }

int render_image(const RenderOptions& opt) {
    // Under mpirun, rank 0 leads: it checks the output, shows progress and writes the image.
    const bool distributed = opt.mpi && opt.mpi->distributed();
    const bool leader = !distributed || opt.mpi->rank() == 0;
    const bool quiet = opt.quiet || !leader;
    if (distributed && (opt.resume || opt.checkpoint_every || opt.display_server))
        throw std::invalid_argument(
            "--resume, --checkpoint-every and --display-server are for one process; a "
            "render across MPI ranks takes none of them");
    // Every mistake on the command line is reported before the scene is loaded.
    glint::RenderSettings checked;
    RenderOverrides early = opt.overrides;
    if (early.crop) {
        // Its form now; whether it fits the image once the scene has given the image's size.
        (void)glint::parse_crop(*early.crop);
        early.crop.reset();
    }
    apply_overrides(early, checked);
    // --threads from here to the image's write (the scene file has no thread count).
    const ThreadLimit thread_limit(checked.threads);
    if (opt.checkpoint_every && !(*opt.checkpoint_every > 0.0))
        throw std::invalid_argument(
            fmt::format("--checkpoint-every: expected a positive number of seconds; got {}", *opt.checkpoint_every));
    std::string output = opt.output;
    if (output.empty())
        output =
            opt.scene_path.empty() ? "spheres.png" : std::filesystem::path(opt.scene_path).stem().string() + ".png";
    if (leader) glint::check_output_path(output);
    check_aov_output(checked, output);
    const std::optional<glint::DisplayAddress> display = display_address(opt);
    // From here on a first Ctrl-C is a request to stop, never a kill that loses the image.
    const std::filesystem::path checkpoint = glint::checkpoint_path_for(output);
    const InterruptGuard interrupt(glint::temporary_path_for(output), glint::temporary_checkpoint_path(checkpoint));

    // The scene file's hash while the scene loads, on a thread of its own: for a large mesh
    // given as the scene, reading and hashing it again took 40-55 ms before the first ray.
    // The load runs on one thread, so this makes two; with --threads 1, it waits its turn.
    std::future<glint::RenderFingerprint> scene_fingerprint =
        std::async(checked.threads == 1 ? std::launch::deferred : std::launch::async, glint::scene_file_fingerprint,
                   std::filesystem::path(opt.scene_path));
    const auto load_start = Clock::now();
    SceneSource source = load_scene(opt.scene_path, opt.scene);
    glint::LoadedScene& loaded = source.loaded;
    auto warn = [&](const std::string& w) {
        if (!quiet) fmt::print(stderr, "warning: {}\n", w);
    };
    for (const std::string& w : loaded.warnings) warn(w);

    glint::RenderSettings& s = loaded.settings;
    apply_overrides(opt.overrides, s);
    check_aov_output(s, output);
    check_memory(s);
    const double load_seconds = seconds_since(load_start);
    if (interrupt.stop()) return stopped_before_rendering(interrupt);

    const auto build_start = Clock::now();
    const glint::RenderScene scene(std::move(loaded.scene));
    const double build_seconds = seconds_since(build_start);
    if (interrupt.stop()) return stopped_before_rendering(interrupt);

    glint::Film film(s.width, s.height);
    glint::TileGrid tiles(s.width, s.height);
    std::optional<glint::AovFilm> aov_film;
    if (!s.aovs.empty()) aov_film.emplace(s.width, s.height, s.aovs);
    glint::AovFilm* const aovs = aov_film ? &*aov_film : nullptr;
    const glint::RenderFingerprint fingerprint = glint::render_fingerprint(scene_fingerprint.get(), s, scene.camera());
    if (opt.resume) {
        glint::read_checkpoint(checkpoint, fingerprint, film, tiles, aovs);
        if (!quiet)
            fmt::print(stderr, "resuming {}: {} of {} tiles were rendered\n", checkpoint.string(), tiles.done_count(),
                       tiles.count());
    }
    if (distributed) opt.mpi->check_same_render(fingerprint);
    const std::unique_ptr<glint::Integrator> integrator = glint::make_integrator(s);
    for (const std::string& w : integrator->warnings(scene)) warn(w);
    if (const uint32_t most = glint::max_render_threads(); s.threads > most)
        warn(fmt::format("--threads {}: this machine runs {} threads at once; rendering with {}", s.threads, most,
                         most));

    // A periodic checkpoint is written by whichever worker finishes a tile once the period
    // is over; the others carry on.
    std::mutex checkpoint_mutex;
    auto last_checkpoint = Clock::now();
    bool checkpoint_failed = false;
    auto save_checkpoint_if_due = [&] {
        if (!opt.checkpoint_every) return;
        const std::unique_lock lock(checkpoint_mutex, std::try_to_lock);
        if (!lock || checkpoint_failed || seconds_since(last_checkpoint) < *opt.checkpoint_every) return;
        try {
            glint::write_checkpoint(checkpoint, fingerprint, film, tiles, aovs);
        } catch (const glint::CheckpointError& e) {
            checkpoint_failed = true;  // say it once; the render goes on
            warn(e.what());
        }
        last_checkpoint = Clock::now();
    };

    std::optional<glint::FilmStream> stream;
    if (display) stream.emplace(*display, output, film, tiles, warn);
    ProgressBar bar(!quiet && ::isatty(STDERR_FILENO));
    const glint::Integrator::ProgressCallback progress = [&](uint32_t done, uint32_t total) {
        bar.update(done, total);
        save_checkpoint_if_due();
    };
    const glint::RenderStats stats =
        distributed ? opt.mpi->render(*integrator, scene, s, film, aovs, progress, interrupt.stop())
                    : integrator->render(scene, s, film, progress, &interrupt.stop(), &tiles, aovs);
    bar.finish();
    if (!leader) return 0;
    if (stream) stream->finish();

    const glint::DisplayTransform display_transform =
        with_display_options(loaded.display, opt.exposure, opt.tone_curve);
    glint::WriteOptions write_options;
    write_options.tone_curve = display_transform.tone_curve;
    // The image with the AOVs' channels after its own (an automatic exposure is chosen from
    // it), the crop's pixels alone with a crop, and what rendered it (kept by EXR).
    auto image = [&](bool sample_counts) {
        glint::Image beauty = film.to_image(sample_counts);
        if (aovs) beauty = aovs->append_to(beauty);
        if (s.crop) beauty = glint::crop_of(beauty, int(s.crop->x0), int(s.crop->y0), int(s.crop->x1), int(s.crop->y1));
        write_options.exposure = glint::exposure_stops(display_transform.exposure, beauty);
        beauty.attributes = fingerprint;
        return beauty;
    };
    if (!stats.complete()) {
        // Interrupted: keep what is rendered. EXR says per pixel how many samples it has
        // (0 where no tile reached); other formats show unrendered pixels black. The
        // checkpoint lets --resume finish the same image.
        glint::write_image(output, image(true), write_options);
        glint::write_checkpoint(checkpoint, fingerprint, film, tiles, aovs);
        fmt::print(stderr,
                   "interrupted: wrote the {} of {} tiles rendered to {}{}; checkpoint {} (continue with --resume)\n",
                   stats.tiles_done, stats.tiles, output,
                   glint::lower_case_extension(output) == ".exr" ? " (channel 'samples': samples per pixel)" : "",
                   checkpoint.string());
        return 128 + interrupt.signal();
    }
    glint::write_image(output, image(false), write_options);
    std::error_code ec;
    std::filesystem::remove(checkpoint, ec);  // the image is whole: nothing to resume

    if (quiet) return 0;
    const double mrays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds * 1e-6 : 0.0;
    std::string spp = fmt::format("{} spp", s.samples_per_axis * s.samples_per_axis);
    if (s.adaptive) {
        // What adaptive sampling spent, not only what it was allowed.
        const glint::PixelRect all = s.crop.value_or(glint::PixelRect{0, 0, s.width, s.height});
        uint64_t samples = 0;
        for (uint32_t y = all.y0; y < all.y1; ++y)
            for (uint32_t x = all.x0; x < all.x1; ++x) samples += film.samples_at(x, y);
        spp = fmt::format("adaptive {} to {} spp ({:.1f} on average)", s.adaptive->min_spp,
                          s.samples_per_axis * s.samples_per_axis,
                          double(samples) / (double(all.width()) * all.height()));
    }
    // What the display transform did, for display formats (float formats keep radiance).
    std::string display_note;
    if (!glint::keeps_radiance(output) && display_transform != glint::DisplayTransform{})
        display_note = fmt::format(" ({}, exposure {}{:+.2f})", glint::tone_curve_name(display_transform.tone_curve),
                                   display_transform.exposure.automatic ? "auto " : "", write_options.exposure);
    const std::string crop =
        s.crop ? fmt::format(" (crop [{}, {}) × [{}, {}))", s.crop->x0, s.crop->x1, s.crop->y0, s.crop->y1) : "";
    const uint32_t threads = glint::max_render_threads();
    const std::string on_threads = fmt::format("on {} thread{}", threads, threads == 1 ? "" : "s");
    fmt::print(
        "{}x{}{}, {}: load {:.2f} s, build {:.2f} s, render {:.2f} s {}, {:.2f} M rays ({:.2f} M rays/s) -> {}{}\n",
        s.width, s.height, crop, spp, load_seconds, build_seconds, stats.seconds, on_threads, double(stats.rays) * 1e-6,
        mrays_per_second, output, display_note);
    return 0;
}

}  // namespace glint::app
