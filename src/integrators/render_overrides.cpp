#include "glint/integrators/render_overrides.h"

#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <span>
#include <stdexcept>

namespace glint {

namespace {

/// "--filter: expected one of box, gaussian, ...; got 'boxy'".
std::string one_of(const std::string& option, std::span<const std::string_view> names, std::string_view got) {
    return fmt::format("{}: expected one of {}; got '{}'", option, fmt::join(names, ", "), got);
}

}  // namespace

std::string option_name(std::string_view name, OptionSpelling spelling) {
    if (spelling == OptionSpelling::CommandLine) return "--" + std::string(name);
    std::string keyword(name);
    std::replace(keyword.begin(), keyword.end(), '-', '_');
    return keyword;
}

uint32_t in_range(std::string_view name, int64_t value, int64_t lo, int64_t hi, std::string_view expected) {
    if (value < lo || value > hi)
        throw std::invalid_argument(fmt::format(
            "{}: expected {}; got {}", name,
            expected.empty() ? fmt::format("an integer from {} to {}", lo, hi) : std::string(expected), value));
    return static_cast<uint32_t>(value);
}

std::vector<Aov> parse_aov_list(std::string_view list, std::string_view option) {
    std::vector<Aov> aovs;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t end = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, end - start);
        const std::optional<Aov> aov = aov_from_name(name);
        if (!aov)
            throw std::invalid_argument(fmt::format("{}: expected a comma-separated list of {}; got '{}'", option,
                                                    fmt::join(aov_names(), ", "), name));
        if (std::find(aovs.begin(), aovs.end(), *aov) == aovs.end()) aovs.push_back(*aov);
        start = end + 1;
    }
    return aovs;
}

CropRequest parse_crop(std::string_view text, std::string_view name) {
    const std::string expected = fmt::format(
        "{}: expected X0,Y0,X1,Y1: the region [X0, X1) × [Y0, Y1) in pixels from the top left, or in fractions of "
        "the image from 0 to 1 (0,0,0.5,0.5: the top-left quarter); got '{}'",
        name, text);
    CropRequest crop;
    std::array<double*, 4> values{&crop.x0, &crop.y0, &crop.x1, &crop.y1};
    std::size_t start = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t end = i + 1 < values.size() ? text.find(',', start) : text.size();
        if (end == std::string_view::npos) throw std::invalid_argument(expected);
        const std::string_view number = text.substr(start, end - start);
        const auto [rest, error] = std::from_chars(number.data(), number.data() + number.size(), *values[i]);
        if (number.empty() || error != std::errc() || rest != number.data() + number.size() ||
            !std::isfinite(*values[i]))
            throw std::invalid_argument(expected);
        crop.fractions = crop.fractions || number.find_first_of(".eE") != std::string_view::npos;
        start = end + 1;
    }
    if (std::min({crop.x0, crop.y0, crop.x1, crop.y1}) < 0.0 || crop.x0 >= crop.x1 || crop.y0 >= crop.y1)
        throw std::invalid_argument(fmt::format("{}: expected 0 ≤ X0 < X1 and 0 ≤ Y0 < Y1; got '{}'", name, text));
    if (crop.fractions && std::max({crop.x1, crop.y1}) > 1.0)
        throw std::invalid_argument(
            fmt::format("{}: fractions of the image go from 0 to 1 (pixels are whole numbers); got '{}'", name, text));
    if (!crop.fractions && std::max({crop.x1, crop.y1}) > double(SettingLimits::kMaxImageSide))
        throw std::invalid_argument(fmt::format("{}: the region reaches past the largest image, {} pixels; got '{}'",
                                                name, SettingLimits::kMaxImageSide, text));
    return crop;
}

PixelRect crop_pixels(const CropRequest& crop, uint32_t width, uint32_t height, std::string_view name) {
    const auto pixels = [&](double v, uint32_t side) {
        return crop.fractions ? uint32_t(std::ceil(v * side)) : uint32_t(v);
    };
    const PixelRect rect{pixels(crop.x0, width), pixels(crop.y0, height), pixels(crop.x1, width),
                         pixels(crop.y1, height)};
    const auto given = [&] {
        return crop.fractions ? fmt::format("{},{},{},{} (pixels {},{},{},{})", crop.x0, crop.y0, crop.x1, crop.y1,
                                            rect.x0, rect.y0, rect.x1, rect.y1)
                              : fmt::format("{},{},{},{}", rect.x0, rect.y0, rect.x1, rect.y1);
    };
    if (rect.x1 > width || rect.y1 > height)
        throw std::invalid_argument(
            fmt::format("{} {}: the region reaches past the {}×{} image", name, given(), width, height));
    if (rect.x0 >= rect.x1 || rect.y0 >= rect.y1)
        throw std::invalid_argument(
            fmt::format("{} {}: the region covers no pixel of the {}×{} image", name, given(), width, height));
    return rect;
}

void apply_overrides(const RenderOverrides& opt, RenderSettings& s, OptionSpelling spelling) {
    using Limits = SettingLimits;
    const auto name = [&](std::string_view option) { return option_name(option, spelling); };
    if (opt.width) s.width = in_range(name("width"), *opt.width, 1, Limits::kMaxImageSide);
    if (opt.height) s.height = in_range(name("height"), *opt.height, 1, Limits::kMaxImageSide);
    if (opt.spp) {
        const std::string expected =
            fmt::format("a square number 1, 4, 9, ... up to {} (N×N stratified samples)", Limits::kMaxSpp);
        const std::optional<uint32_t> n =
            samples_per_axis(in_range(name("spp"), *opt.spp, 1, Limits::kMaxSpp, expected));
        if (!n) throw std::invalid_argument(fmt::format("{}: expected {}; got {}", name("spp"), expected, *opt.spp));
        s.samples_per_axis = *n;
    }
    if (opt.depth) s.max_depth = in_range(name("depth"), *opt.depth, 0, Limits::kMaxDepth);
    if (opt.threads)
        s.threads = in_range(name("threads"), *opt.threads, 0, Limits::kMaxThreads,
                             fmt::format("0 (all cores) or a thread count up to {}", Limits::kMaxThreads));
    if (opt.seed) {
        if (*opt.seed < 0)
            throw std::invalid_argument(
                fmt::format("{}: expected a non-negative integer; got {}", name("seed"), *opt.seed));
        s.seed = static_cast<uint64_t>(*opt.seed);
    }
    if (opt.filter) {
        const std::optional<PixelFilter> filter = filter_from_name(*opt.filter);
        if (!filter) throw std::invalid_argument(one_of(name("filter"), filter_names(), *opt.filter));
        s.filter = *filter;
        s.filter_radius = 0.0f;  // a filter named here takes its own default radius
    }
    if (opt.filter_radius) {
        if (!(*opt.filter_radius > 0.0 && *opt.filter_radius <= Limits::kMaxFilterRadius))
            throw std::invalid_argument(fmt::format("{}: expected a radius in pixels above 0 and at most {}; got {}",
                                                    name("filter-radius"), Limits::kMaxFilterRadius,
                                                    *opt.filter_radius));
        s.filter_radius = static_cast<float>(*opt.filter_radius);
    }
    if (opt.integrator) {
        const std::vector<std::string_view> names = integrator_names();
        if (std::find(names.begin(), names.end(), *opt.integrator) == names.end())
            throw std::invalid_argument(one_of(name("integrator"), names, *opt.integrator));
        s.integrator = *opt.integrator;
    }
    if (opt.light_samples)
        s.light_samples = in_range(name("light-samples"), *opt.light_samples, 1, Limits::kMaxLightSamples);
    if (opt.glossy_samples)
        s.glossy_samples = in_range(name("glossy-samples"), *opt.glossy_samples, 1, Limits::kMaxGlossySamples);
    if (opt.mis) {
        const std::optional<MisHeuristic> mis = mis_heuristic_from_name(*opt.mis);
        if (!mis) throw std::invalid_argument(one_of(name("mis"), mis_heuristic_names(), *opt.mis));
        s.mis = *mis;
    }
    if (opt.aov) s.aovs = parse_aov_list(*opt.aov, name("aov"));
    if (opt.crop) s.crop = crop_pixels(parse_crop(*opt.crop, name("crop")), s.width, s.height, name("crop"));
    if (opt.adaptive || opt.adaptive_threshold) {
        AdaptiveSampling adaptive = s.adaptive.value_or(AdaptiveSampling{});
        if (opt.adaptive_threshold) {
            if (!(*opt.adaptive_threshold > 0.0 && std::isfinite(*opt.adaptive_threshold)))
                throw std::invalid_argument(fmt::format("{}: expected a positive relative error (0.01: 1 %); got {}",
                                                        name("adaptive-threshold"), *opt.adaptive_threshold));
            adaptive.threshold = float(*opt.adaptive_threshold);
        }
        s.adaptive = adaptive;
    }
    // The most samples (the scene's adaptive max_spp, or --spp) must suit the sample order.
    if (s.adaptive) {
        const uint32_t spp = s.samples_per_axis * s.samples_per_axis;
        if (!is_power_of_four(spp))
            throw std::invalid_argument(
                fmt::format("{}: expected a power of 4 (1, 4, 16, 64, ...) with adaptive sampling, the most a pixel "
                            "takes; got {}",
                            name("spp"), spp));
        s.adaptive->min_spp = std::min(s.adaptive->min_spp, spp);
    }
}

}  // namespace glint
