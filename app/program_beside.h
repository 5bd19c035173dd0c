#pragma once
// Commands whose libraries most runs never need are programs of their own, built and
// installed beside `glint`: `glint-view` (SDL2, OpenGL, X11: 50 libraries) and `glint-mpi`
// (Open MPI: 7). `glint` hands the process over to them with its own arguments, as `git`
// runs its subcommands, so that every other command starts without loading them.

#include <string>

namespace glint::app {

/// Replace this process by the program `name` beside this one (the build folder, or `bin/`
/// after `cmake --install`), with the same arguments and environment. Returns only when it
/// could not, saying why ("cannot start PATH: REASON").
[[nodiscard]] std::string run_program_beside(const char* name, int argc, char** argv);

}  // namespace glint::app
