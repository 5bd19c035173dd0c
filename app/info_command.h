#pragma once
// `glint info`: what a scene holds, and for glTF what was mapped and ignored.

#include "scene_source.h"

#include <string>

namespace glint::app {

/// Print the scene's contents to stdout; returns the exit code.
int run_info(const std::string& path, const SceneOptions& options);

}  // namespace glint::app
