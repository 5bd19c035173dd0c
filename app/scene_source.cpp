#include "scene_source.h"

#include "glint/scene/default_scene.h"
#include "glint/scene/environment.h"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

namespace glint::app {

SceneSource load_scene(const std::string& path, const SceneOptions& opt) {
    // The lens options are checked before anything is loaded.
    if (opt.aperture && !(*opt.aperture >= 0.0f && std::isfinite(*opt.aperture)))
        throw std::invalid_argument(
            fmt::format("--aperture: expected a lens radius ≥ 0 in world units (0: a pinhole); got {}", *opt.aperture));
    if (opt.focus && !(*opt.focus > 0.0f && std::isfinite(*opt.focus)))
        throw std::invalid_argument(
            fmt::format("--focus: expected a positive distance in world units; got {}", *opt.focus));
    SceneSource source;
    if (path.empty()) {
        if (!opt.camera.empty())
            throw std::invalid_argument("--camera picks a camera of a glTF file; the built-in scene is not one");
        source.loaded.scene = make_spheres_scene();
        source.loaded.settings.samples_per_axis = 2;
    } else {
        source = load_scene_file(path, SceneFileOptions{opt.camera});
    }
    if (opt.aperture || opt.focus) {
        Camera& camera = source.loaded.scene.camera;
        ThinLens lens = camera.lens();
        if (opt.aperture) lens.aperture_radius = *opt.aperture;
        if (opt.focus) lens.focus_distance = *opt.focus;
        camera.set_lens(lens);
    }
    if (!opt.env.empty()) {
        EnvironmentOptions env;
        if (!opt.env_kind.empty()) env.kind = parse_environment_kind(opt.env_kind);
        env.rotation_degrees = opt.env_rotation;
        env.intensity = opt.env_intensity;
        Scene& scene = source.loaded.scene;
        scene.background = load_environment(opt.env, env);
        // Under the default lighting the environment also replaces the grey ambient sky.
        if (source.default_lighting) scene.ambient_light = average_radiance(scene.background);
    }
    return source;
}

void add_scene_options(CLI::App* cmd, SceneOptions& opt) {
    cmd->add_option("--camera", opt.camera, "glTF camera to render through: name or index (default: the first)");
    cmd->add_option("--aperture", opt.aperture,
                    "Lens aperture radius in world units: depth of field (0 = pinhole, the default)");
    cmd->add_option("--focus", opt.focus, "Distance to the plane of focus in world units (default: the scene's)");
    cmd->add_option("--env", opt.env, "HDR environment map (background and reflections)")->check(CLI::ExistingFile);
    cmd->add_option("--env-kind", opt.env_kind, "Environment layout (default: 2:1 equirect, 1:1 spheremap)")
        ->check(CLI::IsMember({"equirect", "spheremap"}));
    cmd->add_option("--env-rotation", opt.env_rotation, "Environment rotation about +y in degrees");
    cmd->add_option("--env-intensity", opt.env_intensity, "Environment radiance scale")->check(CLI::NonNegativeNumber);
}

}  // namespace glint::app
