#include "scene_source.h"

#include "glint/scene/environment.h"
#include "glint/scene/default_scene.h"

#include <stdexcept>

namespace glint::app {

SceneSource load_scene(const std::string& path, const SceneOptions& opt) {
    SceneSource source;
    if (path.empty()) {
        if (!opt.camera.empty())
            throw std::invalid_argument("--camera picks a camera of a glTF file; the built-in scene is not one");
        source.loaded.scene = make_spheres_scene();
        source.loaded.settings.samples_per_axis = 2;
    } else {
        source = load_scene_file(path, SceneFileOptions{opt.camera});
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
    cmd->add_option("--env", opt.env, "HDR environment map (background and reflections)")->check(CLI::ExistingFile);
    cmd->add_option("--env-kind", opt.env_kind, "Environment layout (default: 2:1 equirect, 1:1 spheremap)")
        ->check(CLI::IsMember({"equirect", "spheremap"}));
    cmd->add_option("--env-rotation", opt.env_rotation, "Environment rotation about +y in degrees");
    cmd->add_option("--env-intensity", opt.env_intensity, "Environment radiance scale")->check(CLI::NonNegativeNumber);
}


}  // namespace glint::app
