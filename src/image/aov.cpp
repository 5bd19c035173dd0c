#include "glint/image/aov.h"

#include <array>

namespace glint {

namespace {

constexpr std::array<std::string_view, 6> kNames{"albedo", "normal", "depth", "position", "spp", "variance"};

}  // namespace

std::span<const std::string_view> aov_names() { return kNames; }

std::optional<Aov> aov_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (kNames[i] == name) return static_cast<Aov>(i);
    return std::nullopt;
}

std::string_view aov_name(Aov aov) { return kNames[static_cast<std::size_t>(aov)]; }

std::vector<std::string> aov_channels(Aov aov) {
    switch (aov) {
        case Aov::Albedo:
            return {"albedo.R", "albedo.G", "albedo.B"};
        case Aov::Normal:
            return {"N.X", "N.Y", "N.Z"};
        case Aov::Depth:
            return {"Z"};
        case Aov::Position:
            return {"P.X", "P.Y", "P.Z"};
        case Aov::Spp:
            return {"spp"};
        case Aov::Variance:
            return {"variance.R", "variance.G", "variance.B"};
    }
    return {};
}

}  // namespace glint
