#include "glint/integrators/render_overrides.h"

#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
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
