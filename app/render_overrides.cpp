#include "render_overrides.h"

#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"

#include <string>
#include <vector>

namespace glint::app {

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
        ->check(CLI::IsMember(
            std::vector<std::string>(glint::mis_heuristic_names().begin(), glint::mis_heuristic_names().end())));
    command->add_flag("--adaptive", o.adaptive,
                      "Adaptive sampling: each pixel stops once its error is small, --spp (a power of 4) at most");
    command->add_option("--adaptive-threshold", o.adaptive_threshold,
                        "Relative error at which an adaptive pixel stops (default 0.01; implies --adaptive)");
    command->add_option("--aov", o.aov,
                        "Extra EXR channels, comma-separated: albedo, normal, depth, position, spp, variance");
}

}  // namespace glint::app
