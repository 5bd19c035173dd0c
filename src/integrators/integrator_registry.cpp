#include "glint/integrators/integrator_registry.h"

#include "glint/integrators/path_integrator.h"
#include "glint/integrators/whitted_integrator.h"

#include <array>
#include <stdexcept>

namespace glint {

namespace {

constexpr std::array kIntegrators{
    IntegratorEntry{"whitted", "Whitted's recursive ray tracer: direct light, mirrors, refraction",
                    &WhittedIntegrator::create},
    IntegratorEntry{"path", "unidirectional path tracer with next-event estimation and MIS", &PathIntegrator::create},
};

// In the order of MisHeuristic.
constexpr std::array<std::string_view, 2> kMisHeuristicNames{"balance", "power"};

}  // namespace

std::span<const IntegratorEntry> integrator_registry() { return kIntegrators; }

std::span<const std::string_view> mis_heuristic_names() { return kMisHeuristicNames; }

std::optional<MisHeuristic> mis_heuristic_from_name(std::string_view name) {
    if (name == "balance") return MisHeuristic::Balance;
    if (name == "power") return MisHeuristic::Power;
    return std::nullopt;
}

std::vector<std::string_view> integrator_names() {
    std::vector<std::string_view> names;
    for (const IntegratorEntry& e : kIntegrators) names.push_back(e.name);
    return names;
}

std::unique_ptr<Integrator> make_integrator(const RenderSettings& settings) {
    for (const IntegratorEntry& e : kIntegrators)
        if (e.name == settings.integrator) return e.create(settings);
    std::string known;
    for (const IntegratorEntry& e : kIntegrators) known += (known.empty() ? "" : ", ") + std::string(e.name);
    throw std::invalid_argument("unknown integrator '" + settings.integrator + "' (expected one of: " + known + ")");
}

}  // namespace glint
