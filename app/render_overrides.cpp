#include "render_overrides.h"

#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include <stdexcept>
#include <vector>

namespace glint::app {

uint32_t in_range(std::string_view name, int64_t value, int64_t lo, int64_t hi, std::string_view expected) {
    if (value < lo || value > hi)
        throw std::invalid_argument(fmt::format(
            "{}: expected {}; got {}", name,
            expected.empty() ? fmt::format("an integer from {} to {}", lo, hi) : std::string(expected), value));
    return static_cast<uint32_t>(value);
}

std::vector<Aov> parse_aov_list(std::string_view list) {
    std::vector<Aov> aovs;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t end = std::min(list.find(',', start), list.size());
        const std::string_view name = list.substr(start, end - start);
        const std::optional<Aov> aov = aov_from_name(name);
        if (!aov)
            throw std::invalid_argument(fmt::format("--aov: expected a comma-separated list of {}; got '{}'",
                                                    fmt::join(aov_names(), ", "), name));
        if (std::find(aovs.begin(), aovs.end(), *aov) == aovs.end()) aovs.push_back(*aov);
        start = end + 1;
    }
    return aovs;
}

void apply_overrides(const RenderOverrides& opt, RenderSettings& s) {
    using Limits = glint::SettingLimits;
    if (opt.width) s.width = in_range("--width", *opt.width, 1, Limits::kMaxImageSide);
    if (opt.height) s.height = in_range("--height", *opt.height, 1, Limits::kMaxImageSide);
    if (opt.spp) {
        const std::string expected =
            fmt::format("a square number 1, 4, 9, ... up to {} (N×N stratified samples)", Limits::kMaxSpp);
        const std::optional<uint32_t> n =
            glint::samples_per_axis(in_range("--spp", *opt.spp, 1, Limits::kMaxSpp, expected));
        if (!n) throw std::invalid_argument(fmt::format("--spp: expected {}; got {}", expected, *opt.spp));
        s.samples_per_axis = *n;
    }
    if (opt.depth) s.max_depth = in_range("--depth", *opt.depth, 0, Limits::kMaxDepth);
    if (opt.threads)
        s.threads = in_range("--threads", *opt.threads, 0, Limits::kMaxThreads,
                             fmt::format("0 (all cores) or a thread count up to {}", Limits::kMaxThreads));
    if (opt.seed) {
        if (*opt.seed < 0)
            throw std::invalid_argument(fmt::format("--seed: expected a non-negative integer; got {}", *opt.seed));
        s.seed = static_cast<uint64_t>(*opt.seed);
    }
    if (opt.filter) {
        s.filter = *glint::filter_from_name(*opt.filter);  // CLI11 checked the name
        s.filter_radius = 0.0f;                            // a filter named here takes its own default radius
    }
    if (opt.filter_radius) {
        if (!(*opt.filter_radius > 0.0 && *opt.filter_radius <= Limits::kMaxFilterRadius))
            throw std::invalid_argument(
                fmt::format("--filter-radius: expected a radius in pixels above 0 and at most {}; got {}",
                            Limits::kMaxFilterRadius, *opt.filter_radius));
        s.filter_radius = static_cast<float>(*opt.filter_radius);
    }
    if (opt.integrator) s.integrator = *opt.integrator;
    if (opt.light_samples)
        s.light_samples = in_range("--light-samples", *opt.light_samples, 1, Limits::kMaxLightSamples);
    if (opt.glossy_samples)
        s.glossy_samples = in_range("--glossy-samples", *opt.glossy_samples, 1, Limits::kMaxGlossySamples);
    if (opt.mis) s.mis = *opt.mis == "balance" ? glint::MisHeuristic::Balance : glint::MisHeuristic::Power;
    if (opt.aov) s.aovs = parse_aov_list(*opt.aov);
    if (opt.adaptive || opt.adaptive_threshold) {
        AdaptiveSampling adaptive = s.adaptive.value_or(AdaptiveSampling{});
        if (opt.adaptive_threshold) {
            if (!(*opt.adaptive_threshold > 0.0 && std::isfinite(*opt.adaptive_threshold)))
                throw std::invalid_argument(
                    fmt::format("--adaptive-threshold: expected a positive relative error (0.01: 1 %); got {}",
                                *opt.adaptive_threshold));
            adaptive.threshold = float(*opt.adaptive_threshold);
        }
        s.adaptive = adaptive;
    }
    // The most samples (the scene's adaptive max_spp, or --spp) must suit the sample order.
    if (s.adaptive) {
        const uint32_t spp = s.samples_per_axis * s.samples_per_axis;
        if (!glint::is_power_of_four(spp))
            throw std::invalid_argument(
                fmt::format("--spp: expected a power of 4 (1, 4, 16, 64, ...) with adaptive sampling, the most a pixel "
                            "takes; got {}",
                            spp));
        s.adaptive->min_spp = std::min(s.adaptive->min_spp, spp);
    }
}

void add_render_overrides(CLI::App* command, RenderOverrides& o) {
    command->add_option("--width", o.width, "Image width in pixels (1 to 16384)");
    command->add_option("--height", o.height, "Image height in pixels (1 to 16384)");
    command->add_option("--spp", o.spp, "Samples per pixel, a square N² (N×N stratified), up to 4096");
    command->add_option("--depth", o.depth, "Maximum reflection/refraction depth (0 to 64)");
    command->add_option("--threads", o.threads, "Worker threads (0 = all cores)");
    command->add_option("--seed", o.seed, "Random seed (a non-negative integer)");
    const std::vector<std::string> filter_names(glint::filter_names().begin(), glint::filter_names().end());
    command->add_option("--filter", o.filter, "Pixel filter")->check(CLI::IsMember(filter_names));
    command->add_option("--filter-radius", o.filter_radius,
                        "Pixel filter radius in pixels, above 0 and at most 16 (default: the filter's)");
    std::vector<std::string> integrator_names;
    for (std::string_view name : glint::integrator_names()) integrator_names.emplace_back(name);
    command->add_option("--integrator", o.integrator, "Integrator (default: the scene's, else whitted)")
        ->check(CLI::IsMember(integrator_names));
    command->add_option("--light-samples", o.light_samples,
                        "Whitted: samples per area light per shading point (1 to 1024)");
    command->add_option("--glossy-samples", o.glossy_samples,
                        "Whitted: samples of a rough surface's glossy reflection and refraction (1 to 1024)");
    command->add_option("--mis", o.mis, "Path: multiple importance sampling heuristic")
        ->check(CLI::IsMember({"balance", "power"}));
    command->add_flag("--adaptive", o.adaptive,
                      "Adaptive sampling: each pixel stops once its error is small, --spp (a power of 4) at most");
    command->add_option("--adaptive-threshold", o.adaptive_threshold,
                        "Relative error at which an adaptive pixel stops (default 0.01; implies --adaptive)");
    command->add_option("--aov", o.aov,
                        "Extra EXR channels, comma-separated: albedo, normal, depth, position, spp, variance");
}

}  // namespace glint::app
