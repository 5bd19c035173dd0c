#include "heatmap.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace glint::app {

namespace {

/// Viridis at nine evenly spaced points (matplotlib's table, sRGB); linear in between.
constexpr std::array<std::array<float, 3>, 9> kViridis = {{{0.267f, 0.005f, 0.329f},
                                                           {0.283f, 0.141f, 0.458f},
                                                           {0.254f, 0.265f, 0.530f},
                                                           {0.207f, 0.372f, 0.553f},
                                                           {0.164f, 0.471f, 0.558f},
                                                           {0.128f, 0.567f, 0.551f},
                                                           {0.135f, 0.659f, 0.518f},
                                                           {0.478f, 0.821f, 0.318f},
                                                           {0.993f, 0.906f, 0.144f}}};

}  // namespace

std::optional<CostKind> cost_kind_from_view_name(std::string_view name) {
    if (name == "nodes") return CostKind::Nodes;
    if (name == "primitives") return CostKind::Primitives;
    if (name == "shadow") return CostKind::ShadowRays;
    if (name == "depth") return CostKind::Depth;
    return std::nullopt;
}

void viridis(float v, uint8_t rgb[3]) {
    const float x = std::clamp(v, 0.0f, 1.0f) * float(kViridis.size() - 1);
    const auto i = std::min(std::size_t(x), kViridis.size() - 2);
    const float f = x - float(i);
    for (int c = 0; c < 3; ++c)
        rgb[c] = uint8_t(std::lround(255.0f * (kViridis[i][c] * (1.0f - f) + kViridis[i + 1][c] * f)));
}

std::vector<uint8_t> heatmap_rgba(const CostMap& map, CostKind kind) {
    const float scale = 1.0f / float(std::max(map.max(kind), 1u));
    std::vector<uint8_t> rgba(map.pixels.size() * 4);
    for (std::size_t i = 0; i < map.pixels.size(); ++i) {
        viridis(float(map.pixels[i].get(kind)) * scale, &rgba[4 * i]);
        rgba[4 * i + 3] = 255;
    }
    return rgba;
}

void draw_heatmap_legend(CostKind kind, uint32_t max) {
    ImGui::Text("%.*s per pixel", int(cost_kind_name(kind).size()), cost_kind_name(kind).data());
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    constexpr int kSteps = 32;
    for (int s = 0; s < kSteps; ++s) {
        uint8_t a[3], b[3];
        viridis(float(s) / kSteps, a);
        viridis(float(s + 1) / kSteps, b);
        const ImU32 left = IM_COL32(a[0], a[1], a[2], 255), right = IM_COL32(b[0], b[1], b[2], 255);
        draw->AddRectFilledMultiColor(ImVec2(at.x + width * float(s) / kSteps, at.y),
                                      ImVec2(at.x + width * float(s + 1) / kSteps, at.y + height), left, right, right,
                                      left);
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::Text("0");
    ImGui::SameLine(width - ImGui::CalcTextSize(std::to_string(max).c_str()).x);
    ImGui::Text("%u", max);
}

}  // namespace glint::app
