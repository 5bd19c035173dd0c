#include "viewer_window.h"

#include "glint/integrators/explanation_format.h"
#include "heatmap.h"
#include "screenshot.h"

#include "glint/image/image_io.h"
#include "glint/integrators/integrator.h"
#include "glint/math/constants.h"
#include "glint/scene/render_scene.h"

#include <SDL_opengl.h>
#include <fmt/core.h>
#include <imgui.h>
#include <imgui_impl_opengl2.h>
#include <imgui_impl_sdl.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace glint::app {

namespace {

constexpr float kOrbitPerPixel = 0.008f;  // radians
constexpr int kClickSlop = 3;             // pixels a click may move and stay a click

}  // namespace

ViewerWindow::ViewerWindow(const RenderScene& scene, const Integrator& integrator, const RenderSettings& settings,
                           ViewerOptions options)
    : scene_(scene), integrator_(integrator), settings_(settings), options_(std::move(options)) {
    // Without a display SDL may pick a driver that shows nothing (offscreen, KMS), and the
    // window would wait forever for input nobody can give.
    const auto unset = [](const char* name) { return !std::getenv(name) || !*std::getenv(name); };
    if (unset("DISPLAY") && unset("WAYLAND_DISPLAY") && unset("SDL_VIDEODRIVER"))
        throw std::runtime_error(
            "cannot open a window: no display (DISPLAY is not set); run under xvfb-run for a "
            "virtual one");
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
        throw std::runtime_error(std::string("cannot open a window: ") + SDL_GetError() +
                                 " (no display? run under xvfb-run for a virtual one)");
    // The image is shown at most 1280×900 on screen; larger images are scaled down.
    scale_ = std::min({1.0f, 1280.0f / float(settings.width), 900.0f / float(settings.height)});
    const int width = int(float(settings.width) * scale_) + kPanelWidth;
    const int height = std::max(int(float(settings.height) * scale_), 600);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    window_ = SDL_CreateWindow("glint view", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height,
                               SDL_WINDOW_OPENGL);
    if (window_) gl_ = SDL_GL_CreateContext(window_);
    if (!window_ || !gl_) {
        const std::string reason = SDL_GetError();
        if (window_) SDL_DestroyWindow(window_);
        SDL_Quit();
        throw std::runtime_error("cannot open a window: " + reason);
    }
    SDL_GL_MakeCurrent(window_, gl_);
    SDL_GL_SetSwapInterval(1);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left behind
    ImGui::StyleColorsDark();
    ImGui_ImplSDL2_InitForOpenGL(window_, gl_);
    ImGui_ImplOpenGL2_Init();
    glGenTextures(1, &texture_);
    render_ = std::make_unique<ProgressiveRender>(scene_, integrator_, settings_, scene_.camera());
}

ViewerWindow::~ViewerWindow() {
    render_.reset();
    glDeleteTextures(1, &texture_);
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    SDL_GL_DeleteContext(gl_);
    SDL_DestroyWindow(window_);
    SDL_Quit();
}

Camera ViewerWindow::camera() const { return orbit_ ? orbit_->camera() : scene_.camera(); }

OrbitCamera ViewerWindow::initial_orbit() const {
    // Pivot about the scene's centre as seen along the view, at least a little ahead.
    const Camera& c = scene_.camera();
    const Bounds3 bounds = scene_.bounds();
    const float ahead = bounds.empty() ? 1.0f : dot(bounds.center() - c.eye(), c.forward());
    const float size = bounds.empty() ? 1.0f : length(bounds.diagonal());
    return OrbitCamera::from(c, std::max(ahead, 0.05f * size));
}

OrbitCamera& ViewerWindow::orbit() {
    if (!orbit_) orbit_ = initial_orbit();
    return *orbit_;
}

void ViewerWindow::camera_changed(bool moving) {
    render_->restart(camera(), moving);
    cost_map_stale_ = true;
}

int ViewerWindow::run() {
    uint64_t last = SDL_GetPerformanceCounter();
    while (!quit_) {
        for (SDL_Event event; SDL_PollEvent(&event);) {
            ImGui_ImplSDL2_ProcessEvent(&event);
            handle(event);
        }
        const uint64_t now = SDL_GetPerformanceCounter();
        fly(float(double(now - last) / double(SDL_GetPerformanceFrequency())));
        last = now;
        run_script();
        if (options_.benchmark_frames > 0) run_benchmark();
        update_texture();

        ImGui_ImplOpenGL2_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        const ImVec2 image_size(float(settings_.width) * scale_, float(settings_.height) * scale_);
        ImGui::GetBackgroundDrawList()->AddImage(ImTextureID(intptr_t(texture_)), ImVec2(0, 0), image_size);
        draw_rays();
        draw_panel();
        ImGui::Render();
        int w = 0, h = 0;
        SDL_GL_GetDrawableSize(window_, &w, &h);
        glViewport(0, 0, w, h);
        glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
        if (!screenshot_path_.empty()) {
            write_screenshot(window_, screenshot_path_);
            screenshot_path_.clear();
        }
        SDL_GL_SwapWindow(window_);
        SDL_Delay(4);  // a virtual display does not wait for vsync
    }
    return 0;
}

void ViewerWindow::handle(const SDL_Event& event) {
    const ImGuiIO& io = ImGui::GetIO();
    // The image is left of the panel: what happens over it is the viewer's, not ImGui's.
    const int image_right = int(float(settings_.width) * scale_);
    switch (event.type) {
        case SDL_QUIT:
            quit_ = true;
            break;
        case SDL_KEYDOWN:
            if (!io.WantCaptureKeyboard && !event.key.repeat) handle_key(event.key.keysym.sym);
            break;
        case SDL_MOUSEBUTTONDOWN:
            if (event.button.x >= image_right) break;
            left_ = left_ || event.button.button == SDL_BUTTON_LEFT;
            middle_ = middle_ || event.button.button == SDL_BUTTON_MIDDLE;
            right_ = right_ || event.button.button == SDL_BUTTON_RIGHT;
            press_x_ = event.button.x;
            press_y_ = event.button.y;
            dragged_ = false;
            break;
        case SDL_MOUSEMOTION: {
            if (!(left_ || middle_ || right_)) break;
            const float dx = float(event.motion.xrel), dy = float(event.motion.yrel);
            if (std::abs(event.motion.x - press_x_) > kClickSlop || std::abs(event.motion.y - press_y_) > kClickSlop)
                dragged_ = true;
            const bool pan = middle_ || (left_ && (SDL_GetModState() & KMOD_SHIFT));
            if (pan) {
                // A pixel of drag moves the target by a pixel's worth of the view at its distance.
                const float view = 2.0f * std::tan(0.5f * radians(camera().vertical_fov()));
                const float per_pixel = view / (float(settings_.height) * scale_);
                orbit().pan(-dx * per_pixel, dy * per_pixel);
            } else {
                orbit().orbit(-dx * kOrbitPerPixel, dy * kOrbitPerPixel);
            }
            camera_changed(true);
            break;
        }
        case SDL_MOUSEBUTTONUP: {
            const bool was_left = event.button.button == SDL_BUTTON_LEFT && left_;
            if (event.button.button == SDL_BUTTON_LEFT) left_ = false;
            if (event.button.button == SDL_BUTTON_MIDDLE) middle_ = false;
            if (event.button.button == SDL_BUTTON_RIGHT) right_ = false;
            if (dragged_ && !(left_ || middle_ || right_)) {
                camera_changed(false);  // at rest: refine
                dragged_ = false;
            } else if (was_left && !dragged_) {
                explain_pixel(int(float(event.button.x) / scale_), int(float(event.button.y) / scale_));
            }
            break;
        }
        case SDL_MOUSEWHEEL:
            if (event.wheel.mouseX >= image_right || event.wheel.y == 0) break;
            orbit().dolly(std::pow(0.9f, float(event.wheel.y)));
            camera_changed(false);
            break;
        default:
            break;
    }
}

void ViewerWindow::handle_key(SDL_Keycode key) {
    if (right_) return;  // W, A, S, D fly while the right button is held (fly())
    switch (key) {
        case SDLK_ESCAPE:
            quit_ = true;
            break;
        case SDLK_f:
            orbit().frame(scene_.bounds());
            camera_changed(false);
            break;
        case SDLK_r:
            orbit_.reset();  // the scene's own camera, exactly
            camera_changed(false);
            break;
        case SDLK_p:
            fmt::print("{}", (orbit_ ? *orbit_ : initial_orbit()).toml());
            break;
        case SDLK_s:
            save(options_.output);
            break;
        default:
            break;
    }
    std::fflush(stdout);
}

void ViewerWindow::fly(float seconds) {
    if (!right_) return;
    const uint8_t* keys = SDL_GetKeyboardState(nullptr);
    const float r = float(keys[SDL_SCANCODE_D]) - float(keys[SDL_SCANCODE_A]);
    const float u = float(keys[SDL_SCANCODE_E]) - float(keys[SDL_SCANCODE_Q]);
    const float f = float(keys[SDL_SCANCODE_W]) - float(keys[SDL_SCANCODE_S]);
    if (r == 0.0f && u == 0.0f && f == 0.0f) return;
    // Half the scene's size per second.
    const float speed = 0.5f * std::max(length(scene_.bounds().diagonal()), 1e-3f) * std::min(seconds, 0.1f);
    orbit().fly(r * speed, u * speed, f * speed);
    dragged_ = true;  // refine when the button is released
    camera_changed(true);
}

void ViewerWindow::explain_pixel(int x, int y) {
    if (x < 0 || y < 0 || x >= int(settings_.width) || y >= int(settings_.height)) return;
    const Camera view = camera();
    explained_ = integrator_.explain(scene_, settings_, uint32_t(x), uint32_t(y), 0u, &view);
    explanation_ = explanation_text(scene_, settings_, *explained_);
    // ImGui's built-in font has no Σ or ×.
    panel_text_ = explanation_;
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"Σ", "sum of"}, {"×", "x"}})
        for (std::size_t at; (at = panel_text_.find(from)) != std::string::npos;)
            panel_text_.replace(at, from.size(), to);
    fmt::print("{}", explanation_);
    std::fflush(stdout);
}

float ViewerWindow::exposure_stops(const Image& image) const {
    return glint::exposure_stops(options_.display.exposure, image);
}

void ViewerWindow::save(const std::string& path) {
    const std::shared_ptr<const Film> film = render_->accumulated();
    if (!film) {
        message_ = "nothing to save yet: no full-resolution pass has finished";
    } else {
        WriteOptions write_options;
        const Image image = film->to_image();
        write_options.exposure = exposure_stops(image);
        write_options.tone_curve = options_.display.tone_curve;
        try {
            write_image(path, image, write_options);
            message_ = fmt::format("saved {} ({} spp)", path, render_->status().passes);
        } catch (const std::exception& e) {
            message_ = e.what();
        }
    }
    fmt::print("{}\n", message_);
    std::fflush(stdout);
}

void ViewerWindow::run_benchmark() {
    const double frequency = double(SDL_GetPerformanceFrequency());
    const uint64_t now = SDL_GetPerformanceCounter();
    if (benchmark_.frame == 0) benchmark_.start = now;
    if (benchmark_.frame < options_.benchmark_frames) {
        // A full turn over the frames, as a steady drag would make it.
        orbit().orbit(2.0f * kPi / float(options_.benchmark_frames), 0.0f);
        camera_changed(true);
        if (render_->newest_version() != benchmark_.seen_version) {
            benchmark_.seen_version = render_->newest_version();
            ++benchmark_.images;
        }
        ++benchmark_.frame;
        return;
    }
    if (benchmark_.frame == options_.benchmark_frames) {
        const double seconds = double(now - benchmark_.start) / frequency;
        fmt::print("orbiting: {} frames in {:.2f} s, {:.1f} frames/s, {:.1f} new coarse images/s ({}x{})\n",
                   benchmark_.frame, seconds, benchmark_.frame / seconds, double(benchmark_.images) / seconds,
                   std::max(1u, settings_.width / 4), std::max(1u, settings_.height / 4));
        camera_changed(false);
        benchmark_.converge_start = now;
        ++benchmark_.frame;
        return;
    }
    const ViewStatus status = render_->status();
    if (status.preview || status.passes < status.total_passes) return;
    const uint32_t threads = max_render_threads();
    fmt::print("at rest: converged {}x{} at {} spp in {:.2f} s on {} thread{}\n", settings_.width, settings_.height,
               status.total_passes, double(now - benchmark_.converge_start) / frequency, threads,
               threads == 1 ? "" : "s");
    std::fflush(stdout);
    quit_ = true;
}

void ViewerWindow::run_script() {
    if (next_step_ >= options_.script.size()) return;
    const ScriptStep& step = options_.script[next_step_];
    const ViewStatus status = render_->status();
    switch (step.kind) {
        case ScriptStep::Kind::WaitConverged:
            if (status.preview || status.passes < status.total_passes) return;
            break;
        case ScriptStep::Kind::WaitPasses:
            if (status.preview || status.passes < uint32_t(step.a)) return;
            break;
        case ScriptStep::Kind::WaitFrames:
            if (++frames_waited_ < step.a) return;
            frames_waited_ = 0;
            break;
        case ScriptStep::Kind::Save:
            save(step.text);
            break;
        case ScriptStep::Kind::Show:
            show(cost_kind_from_view_name(step.text));
            break;
        case ScriptStep::Kind::Screenshot:
            screenshot_path_ = step.text;
            break;
        case ScriptStep::Kind::Quit:
            quit_ = true;
            break;
        default:
            push_script_events(step, int(float(settings_.width) * scale_ * 0.5f),
                               int(float(settings_.height) * scale_ * 0.5f), scale_);
            break;
    }
    ++next_step_;
}

}  // namespace glint::app
