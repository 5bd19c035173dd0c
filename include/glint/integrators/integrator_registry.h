#pragma once
/// \file The integrators Glint knows, by name: one explicit table (no self-registration,
/// which a static library would silently drop). Adding an integrator is one line in
/// src/integrators/integrator_registry.cpp beside its two files.

#include "glint/integrators/integrator.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct IntegratorEntry {
    std::string_view name;
    std::string_view description;
    std::unique_ptr<Integrator> (*create)(const RenderSettings& settings);
};

/// Every integrator, in the order `glint render --help` lists them.
[[nodiscard]] std::span<const IntegratorEntry> integrator_registry();
/// Their names, for choices in scene files and on the command line.
[[nodiscard]] std::vector<std::string_view> integrator_names();
/// The names of the MIS heuristics (MisHeuristic), for choices in scene files and options.
[[nodiscard]] std::span<const std::string_view> mis_heuristic_names();
/// The heuristic `name` names ("balance", "power"); nullopt for another name.
[[nodiscard]] std::optional<MisHeuristic> mis_heuristic_from_name(std::string_view name);
/// The integrator `settings.integrator` names, made from the settings; throws
/// std::invalid_argument naming the known ones for an unknown name.
[[nodiscard]] std::unique_ptr<Integrator> make_integrator(const RenderSettings& settings);

}  // namespace glint
