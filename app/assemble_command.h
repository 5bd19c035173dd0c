#pragma once
// `glint assemble`: the crops of one render (`glint render --crop`, written as EXR with
// their place in the frame) joined into the frame one render would have made.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace glint::app {

struct AssembleOptions {
    std::vector<std::string> parts;
    std::string output;
};

/// Add the `assemble` subcommand's arguments to `command`.
void add_assemble_options(CLI::App* command, AssembleOptions& options);

/// Run `glint assemble`; returns the exit status. Throws on every error, with a message for
/// the user, before anything is written.
int run_assemble(const AssembleOptions& options);

}  // namespace glint::app
