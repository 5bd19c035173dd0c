#include "viewer_window.h"

#include "heatmap.h"

#include "glint/scene/render_scene.h"

#include <SDL_opengl.h>
#include <fmt/core.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

// The window's drawing: the image or heatmap texture, the rays of the explained pixel and the
// side panel (the event handling and the session are in viewer_window.cpp).

namespace glint::app {

namespace {

/// IEC 61966-2-1 sRGB encoding of a linear value, to 8 bits.
uint8_t srgb8(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    const float encoded = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(encoded * 255.0f));
}

ImU32 ray_colour(const RayTreeNode& node) {
    switch (node.kind) {
        case RayKind::Camera:
            return IM_COL32(255, 255, 255, 255);
        case RayKind::Reflection:
            return IM_COL32(80, 220, 255, 255);
        case RayKind::Refraction:
            return IM_COL32(120, 255, 120, 255);
        case RayKind::Shadow:
            return node.blocked ? IM_COL32(255, 70, 70, 255) : IM_COL32(255, 230, 80, 255);
        case RayKind::Bounce:
            return IM_COL32(255, 160, 60, 255);
        // The glossy kinds in paler tints of the mirror's and the refraction's colours.
        case RayKind::GlossyReflection:
            return IM_COL32(170, 225, 255, 255);
        case RayKind::GlossyTransmission:
            return IM_COL32(190, 255, 170, 255);
    }
    return IM_COL32(255, 255, 255, 255);
}

}  // namespace

void ViewerWindow::upload_newest() {
    const std::shared_ptr<const Film> film = render_->newest(shown_version_);
    if (!film) return;
    const float gain = std::exp2(options_.display.exposure.automatic ? exposure_stops(film->to_image())
                                                                     : options_.display.exposure.stops);
    std::vector<uint8_t> rgba(std::size_t(film->width()) * film->height() * 4);
    for (uint32_t y = 0; y < film->height(); ++y)
        for (uint32_t x = 0; x < film->width(); ++x) {
            const Color c = apply_tone_curve(options_.display.tone_curve, film->at(x, y) * gain);
            uint8_t* p = &rgba[(std::size_t(y) * film->width() + x) * 4];
            p[0] = srgb8(c.r);
            p[1] = srgb8(c.g);
            p[2] = srgb8(c.b);
            p[3] = 255;
        }
    upload_rgba(rgba, film->width(), film->height());
}

void ViewerWindow::upload_rgba(const std::vector<uint8_t>& rgba, uint32_t width, uint32_t height) const {
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    // The coarse first frame is shown in blocks; a full one as smooth as the window allows.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, width < settings_.width ? GL_NEAREST : GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, GLsizei(width), GLsizei(height), 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

void ViewerWindow::show(std::optional<CostKind> kind) {
    shown_kind_ = kind;
    cost_map_stale_ = true;
    shown_version_ = ~uint64_t(0);  // the image is uploaded again when it is shown again
}

void ViewerWindow::update_texture() {
    // While the camera moves the image's coarse frames are shown, heatmap or not: a heatmap
    // is computed at full resolution once the camera rests.
    const bool moving = (left_ || middle_ || right_) && dragged_;
    if (!shown_kind_ || moving) {
        if (showing_heatmap_) shown_version_ = ~uint64_t(0);
        showing_heatmap_ = false;
        upload_newest();
        return;
    }
    if (showing_heatmap_ && !cost_map_stale_) return;
    cost_map_ = compute_cost_map(scene_, integrator_, settings_, camera());
    upload_rgba(heatmap_rgba(*cost_map_, *shown_kind_), settings_.width, settings_.height);
    showing_heatmap_ = true;
    cost_map_stale_ = false;
    fmt::print("heatmap {}: 0 to {}\n", cost_kind_name(*shown_kind_), cost_map_->max(*shown_kind_));
    std::fflush(stdout);
}

void ViewerWindow::draw_rays() const {
    if (!explained_ || explained_->samples.empty() || !explained_->samples[0].tree) return;
    const RayTree& tree = *explained_->samples[0].tree;
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    // Drawn through the current camera, so the rays stay on the scene when the view moves.
    const Camera view = camera();
    auto on_screen = [&](const Vec3& p) -> std::optional<ImVec2> {
        const auto q = view.project(p, int(settings_.width), int(settings_.height));
        if (!q) return std::nullopt;
        return ImVec2(q->x * scale_, q->y * scale_);
    };
    const float reach = 2.0f * std::max(length(scene_.bounds().diagonal()), 1.0f);
    for (const RayTreeNode& node : tree.nodes()) {
        const float t = (node.hit || node.kind == RayKind::Shadow) && std::isfinite(node.t) ? node.t : reach;
        const auto a = on_screen(node.origin);
        const auto b = on_screen(node.origin + node.direction * std::min(t, reach));
        if (node.kind == RayKind::Camera) {
            if (b) draw->AddCircle(*b, 5.0f, ray_colour(node), 0, 2.0f);
        } else if (a && b) {
            draw->AddLine(*a, *b, ray_colour(node), 2.0f);
        }
    }
}

void ViewerWindow::draw_panel() {
    const float x = float(settings_.width) * scale_;
    ImGui::SetNextWindowPos(ImVec2(x, 0));
    ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), ImGui::GetIO().DisplaySize.y));
    ImGui::Begin("glint", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    const ViewStatus status = render_->status();
    if (status.preview)
        ImGui::Text("preview (1/4 resolution, 1 spp)");
    else
        ImGui::Text("%u of %u spp%s", status.passes, status.total_passes,
                    status.passes == status.total_passes ? ": converged" : "");
    ImGui::Text("%.2f M rays/s, %s integrator", status.rays_per_second * 1e-6, settings_.integrator.c_str());
    if (ImGui::Button("Frame (F)")) handle_key(SDLK_f);
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) handle_key(SDLK_r);
    ImGui::SameLine();
    if (ImGui::Button("Camera (P)")) handle_key(SDLK_p);
    ImGui::SameLine();
    if (ImGui::Button("Save (S)")) handle_key(SDLK_s);
    if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    static constexpr const char* kViews[] = {"image", "BVH nodes visited", "primitives tested", "shadow rays",
                                             "ray depth reached"};
    int view = shown_kind_ ? int(*shown_kind_) + 1 : 0;
    if (ImGui::Combo("show", &view, kViews, IM_ARRAYSIZE(kViews)))
        show(view == 0 ? std::nullopt : std::optional<CostKind>(CostKind(view - 1)));
    if (shown_kind_ && cost_map_) draw_heatmap_legend(*shown_kind_, cost_map_->max(*shown_kind_));
    ImGui::Separator();
    ImGui::TextWrapped(
        "Left drag: orbit. Middle or shift + left drag: pan. Wheel: dolly. Right button + W A S D Q E: fly. "
        "Click: explain the pixel.");
    ImGui::Separator();
    ImGui::BeginChild("explanation", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(explanation_.empty() ? "Click the image to see a pixel's rays." : panel_text_.c_str());
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace glint::app
