#pragma once
// The `glint view` window: SDL2 for the window and input, OpenGL 2 to show the image, Dear
// ImGui for the side panel. It owns the interactive camera and hands every change to the
// render thread (progressive_render.h).
//
// Controls: left drag orbits, middle drag (or shift + left) pans, the wheel dollies; hold the
// right button to fly with W, A, S, D (and Q, E down and up) while the mouse turns the view;
// F frames the scene, R returns to the scene's camera, P prints it as a [camera] table, S
// saves the accumulated image, a left click explains the pixel under the mouse, Esc quits.

#include "progressive_render.h"
#include "session_script.h"

#include "glint/image/display_transform.h"
#include "glint/integrators/cost_map.h"
#include "glint/integrators/ray_tree.h"
#include "glint/scene/orbit_camera.h"

#include <SDL.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint::app {

struct ViewerOptions {
    std::string output;
    /// How the window and saved PNGs show radiance (EXR keeps it).
    DisplayTransform display;
    std::vector<ScriptStep> script;
    /// Measure instead of waiting for a user: orbit for this many frames, then time the
    /// render to convergence, print both and close.
    int benchmark_frames = 0;
};

class ViewerWindow {
public:
    ViewerWindow(const RenderScene& scene, const Integrator& integrator, const RenderSettings& settings,
                 ViewerOptions options);
    ~ViewerWindow();
    ViewerWindow(const ViewerWindow&) = delete;
    ViewerWindow& operator=(const ViewerWindow&) = delete;

    /// Show the window until it is closed; returns the exit status.
    int run();

private:
    /// Width of the side panel, right of the image, in window pixels.
    static constexpr int kPanelWidth = 400;

    [[nodiscard]] Camera camera() const;
    /// The orbit that starts at the scene's camera.
    [[nodiscard]] OrbitCamera initial_orbit() const;
    /// The orbit camera, made from the scene's camera on the first move.
    OrbitCamera& orbit();
    void camera_changed(bool moving);

    void handle(const SDL_Event& event);
    void handle_key(SDL_Keycode key);
    void fly(float seconds);
    void run_script();
    /// One frame of --benchmark: orbit a step, or once the frames are done wait for convergence.
    void run_benchmark();

    void explain_pixel(int x, int y);
    void save(const std::string& path);
    /// The display exposure for `image`: the chosen stops, or the meter's when automatic.
    [[nodiscard]] float exposure_stops(const Image& image) const;
    void upload_newest();
    void upload_rgba(const std::vector<uint8_t>& rgba, uint32_t width, uint32_t height) const;
    /// Show the image (none) or a heatmap of `kind`.
    void show(std::optional<CostKind> kind);
    /// The texture for this frame: the newest image, or the heatmap once the camera rests.
    void update_texture();
    void draw_panel();
    void draw_rays() const;

    const RenderScene& scene_;
    const Integrator& integrator_;
    const RenderSettings settings_;
    ViewerOptions options_;

    SDL_Window* window_ = nullptr;
    SDL_GLContext gl_ = nullptr;
    unsigned texture_ = 0;
    float scale_ = 1.0f;  ///< window pixels per image pixel

    std::optional<OrbitCamera> orbit_;
    std::unique_ptr<ProgressiveRender> render_;
    uint64_t shown_version_ = 0;

    // Mouse state, from events (scripted events do not move SDL's own cursor).
    bool left_ = false, middle_ = false, right_ = false, dragged_ = false;
    int press_x_ = 0, press_y_ = 0;

    std::optional<CostKind> shown_kind_;
    std::optional<CostMap> cost_map_;
    bool cost_map_stale_ = true, showing_heatmap_ = false;

    std::optional<PixelExplanation> explained_;
    std::string explanation_, panel_text_;
    std::string message_;

    std::string screenshot_path_;
    std::size_t next_step_ = 0;
    int frames_waited_ = 0;
    bool quit_ = false;

    struct Benchmark {
        int frame = 0;
        uint64_t images = 0;  ///< new images shown while orbiting
        uint64_t seen_version = 0;
        uint64_t start = 0, converge_start = 0;
    } benchmark_;
};

}  // namespace glint::app
