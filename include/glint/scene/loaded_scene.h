#pragma once
/// \file What every loader produces: a scene and the render settings its file asks for.

#include "glint/image/display_transform.h"
#include "glint/integrators/render_settings.h"
#include "glint/scene/scene.h"

#include <string>
#include <vector>

namespace glint {

/// The scene, the render settings and display transform the file asks for, and warnings about what the loader
/// could not map (the render goes on without it).
struct LoadedScene {
    Scene scene;
    RenderSettings settings;
    /// How PNG/JPEG output is exposed and tone mapped (--exposure and --tonemap override it).
    DisplayTransform display;
    std::vector<std::string> warnings;
};

}  // namespace glint
