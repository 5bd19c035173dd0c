#pragma once
// The viewer's render thread: passes of Integrator::render_pass over a film, one sample per
// pixel each, restarted whenever the camera moves. Every restart begins with a pass at a
// quarter of the resolution (a fast first frame); while the camera keeps moving only that
// coarse pass is drawn, and once it rests the full-resolution passes accumulate until the
// settings' N×N samples are in. With the scene's own camera and no move, the finished film
// is the one `glint render` makes, bit for bit.

#include "glint/image/film.h"
#include "glint/integrators/integrator.h"
#include "glint/integrators/render_settings.h"
#include "glint/scene/camera.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>

namespace glint {
class RenderScene;
}

namespace glint::app {

struct ViewStatus {
    /// Full-resolution passes finished since the last restart, of `total_passes`.
    uint32_t passes = 0;
    uint32_t total_passes = 0;
    /// The newest image is the coarse first frame.
    bool preview = true;
    /// Rays per second of the last pass.
    double rays_per_second = 0.0;
};

class ProgressiveRender {
public:
    ProgressiveRender(const RenderScene& scene, const Integrator& integrator, const RenderSettings& settings,
                      const Camera& camera);
    ~ProgressiveRender();
    ProgressiveRender(const ProgressiveRender&) = delete;
    ProgressiveRender& operator=(const ProgressiveRender&) = delete;

    /// Start over with `camera`; while `moving`, only the coarse pass is drawn.
    void restart(const Camera& camera, bool moving);

    /// The newest film (coarse or full) if it changed since `version`, which is updated.
    [[nodiscard]] std::shared_ptr<const Film> newest(uint64_t& version) const;
    /// The full-resolution film of the passes finished so far (null before the first).
    [[nodiscard]] std::shared_ptr<const Film> accumulated() const;
    [[nodiscard]] ViewStatus status() const;
    /// Counts the images published so far (coarse and full).
    [[nodiscard]] uint64_t newest_version() const;

private:
    void run();

    const RenderScene& scene_;
    const Integrator& integrator_;
    const RenderSettings settings_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    Camera camera_;
    bool moving_ = false;
    uint64_t generation_ = 0;
    bool quit_ = false;
    bool rendering_coarse_ = false;
    std::atomic<bool> stop_pass_{false};
    std::shared_ptr<const Film> newest_, accumulated_;
    uint64_t version_ = 0;
    ViewStatus status_;
    std::thread thread_;
};

}  // namespace glint::app
