#include "progressive_render.h"

#include <algorithm>

namespace glint::app {

ProgressiveRender::ProgressiveRender(const RenderScene& scene, const Integrator& integrator,
                                     const RenderSettings& settings, const Camera& camera)
    : scene_(scene), integrator_(integrator), settings_(settings), camera_(camera) {
    status_.total_passes = settings.samples_per_axis * settings.samples_per_axis;
    thread_ = std::thread([this] { run(); });
}

ProgressiveRender::~ProgressiveRender() {
    {
        const std::lock_guard lock(mutex_);
        quit_ = true;
    }
    stop_pass_ = true;
    wake_.notify_all();
    thread_.join();
}

void ProgressiveRender::restart(const Camera& camera, bool moving) {
    {
        const std::lock_guard lock(mutex_);
        camera_ = camera;
        moving_ = moving;
        ++generation_;
        accumulated_.reset();
        status_.passes = 0;
        status_.preview = true;
        // A coarse pass in flight finishes while the camera keeps moving: cut short at every
        // mouse event, a slow scene would show nothing until the camera stops.
        if (!(moving && rendering_coarse_)) stop_pass_ = true;
    }
    wake_.notify_all();
}

std::shared_ptr<const Film> ProgressiveRender::newest(uint64_t& version) const {
    const std::lock_guard lock(mutex_);
    if (version == version_) return nullptr;
    version = version_;
    return newest_;
}

std::shared_ptr<const Film> ProgressiveRender::accumulated() const {
    const std::lock_guard lock(mutex_);
    return accumulated_;
}

uint64_t ProgressiveRender::newest_version() const {
    const std::lock_guard lock(mutex_);
    return version_;
}

ViewStatus ProgressiveRender::status() const {
    const std::lock_guard lock(mutex_);
    return status_;
}

void ProgressiveRender::run() {
    // A quarter of the resolution, at least one pixel: 1/16 of the work for the first frame.
    const uint32_t coarse_width = std::max(1u, settings_.width / 4), coarse_height = std::max(1u, settings_.height / 4);
    uint64_t rendered_generation = ~uint64_t(0);
    bool coarse_done = false;
    std::unique_ptr<Film> film;
    uint32_t pass = 0;
    for (;;) {
        Camera camera;
        bool moving = false;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] {
                if (quit_) return true;
                if (generation_ != rendered_generation) return true;
                return !moving_ && pass < status_.total_passes;
            });
            if (quit_) return;
            if (generation_ != rendered_generation) {
                rendered_generation = generation_;
                coarse_done = false;
                pass = 0;
                film.reset();
            }
            camera = camera_;
            moving = moving_;
            stop_pass_ = false;
        }
        const uint64_t generation = rendered_generation;
        if (!coarse_done) {
            auto coarse = std::make_shared<Film>(coarse_width, coarse_height);
            {
                const std::lock_guard lock(mutex_);
                rendering_coarse_ = true;
            }
            const RenderStats stats = integrator_.render_pass(scene_, camera, settings_, *coarse, 0, &stop_pass_);
            coarse_done = true;
            const std::lock_guard lock(mutex_);
            rendering_coarse_ = false;
            // Shown even if the camera has moved on since: the next one follows at once.
            if (!stats.complete()) continue;
            newest_ = std::move(coarse);
            ++version_;
            status_.rays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds : 0.0;
            continue;
        }
        if (moving) continue;
        if (!film) film = std::make_unique<Film>(settings_.width, settings_.height);
        const RenderStats stats = integrator_.render_pass(scene_, camera, settings_, *film, pass, &stop_pass_);
        const std::lock_guard lock(mutex_);
        if (!stats.complete() || generation_ != generation) continue;
        ++pass;
        auto finished = std::make_shared<const Film>(*film);
        newest_ = finished;
        accumulated_ = std::move(finished);
        ++version_;
        status_.passes = pass;
        status_.preview = false;
        status_.rays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds : 0.0;
    }
}

}  // namespace glint::app
