#include "scene_source.h"

#include "glint/scene/default_scene.h"
#include "glint/scene/environment.h"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

namespace glint::app {

namespace {

/// The shutter --shutter OPEN,CLOSE or --time T asks for, checked before anything is loaded.
std::optional<Shutter> shutter_option(const SceneOptions& opt) {
    if (opt.frame_shutter) return opt.frame_shutter;
    if (opt.shutter && opt.time) throw std::invalid_argument("--time and --shutter: expected one of them, not both");
    if (opt.time) {
        if (!std::isfinite(*opt.time))
            throw std::invalid_argument(fmt::format("--time: expected a finite time; got {}", *opt.time));
        return Shutter{*opt.time, *opt.time};
    }
    if (!opt.shutter) return std::nullopt;
    const std::string& text = *opt.shutter;
    const auto comma = text.find(',');
    Shutter shutter;
    try {
        std::size_t used_open = 0, used_close = 0;
        if (comma == std::string::npos) throw std::invalid_argument("no comma");
        shutter.open = std::stof(text.substr(0, comma), &used_open);
        shutter.close = std::stof(text.substr(comma + 1), &used_close);
        if (used_open != comma || used_close != text.size() - comma - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
        throw std::invalid_argument(
            fmt::format("--shutter: expected OPEN,CLOSE (two times, e.g. 0,0.5); got '{}'", text));
    }
    if (!std::isfinite(shutter.open) || !std::isfinite(shutter.close) || shutter.close < shutter.open)
        throw std::invalid_argument(
            fmt::format("--shutter: expected finite times with CLOSE at or after OPEN; got '{}'", text));
    return shutter;
}

}  // namespace

SceneSource load_scene(const std::string& path, const SceneOptions& opt) {
    const std::optional<Shutter> shutter = shutter_option(opt);
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
        if (!opt.up.empty())
            throw std::invalid_argument(
                "--up orients the automatic camera of a mesh or glTF file; the built-in "
                "scene has its own camera");
        source.loaded = make_default_scene();
    } else {
        const std::optional<UpAxis> up = opt.up.empty() ? std::nullopt : parse_up_axis(opt.up);
        source = load_scene_file(path, SceneFileOptions{opt.camera, shutter, up});
    }
    if (opt.aperture || opt.focus) {
        Camera& camera = source.loaded.scene.camera;
        ThinLens lens = camera.lens();
        if (opt.aperture) lens.aperture_radius = *opt.aperture;
        if (opt.focus) lens.focus_distance = *opt.focus;
        camera.set_lens(lens);
    }
    if (shutter) source.loaded.scene.camera.set_shutter(*shutter);
    if (!opt.env.empty()) {
        EnvironmentOptions env;
        if (!opt.env_kind.empty()) env.kind = parse_environment_kind(opt.env_kind);
        env.rotation_degrees = opt.env_rotation;
        env.intensity = opt.env_intensity;
        Scene& scene = source.loaded.scene;
        scene.background = load_environment(opt.env, env);
        // Under the default lighting the environment also replaces the grey ambient sky: as a
        // light, whose samples are shadow-tested, in both integrators.
        if (source.default_lighting) {
            scene.ambient_light = Color(0.0f);
            scene.environment_lighting = true;
        }
    }
    return source;
}

void add_scene_options(CLI::App* cmd, SceneOptions& opt) {
    cmd->add_option("--camera", opt.camera, "glTF camera to render through: name or index (default: the first)");
    cmd->add_option("--up", opt.up,
                    "Up axis of a mesh or glTF file's automatic camera: x, y or z (scans, CAD); default: the axis an "
                    "FBX file declares, else y")
        ->check(CLI::IsMember({"x", "y", "z"}));
    cmd->add_option("--aperture", opt.aperture,
                    "Lens aperture radius in world units: depth of field (0 = pinhole, the default)");
    cmd->add_option("--focus", opt.focus, "Distance to the plane of focus in world units (default: the scene's)");
    cmd->add_option("--shutter", opt.shutter,
                    "OPEN,CLOSE: when the shutter is open, in scene time (motion blur; default: the scene's)");
    cmd->add_option("--time", opt.time, "Render the instant T of scene time: no motion blur (the shutter [T, T])");
    cmd->add_option("--env", opt.env, "HDR environment map (background and reflections)")->check(CLI::ExistingFile);
    cmd->add_option("--env-kind", opt.env_kind,
                    "Environment layout: equirect, spheremap or angmap (default: 2:1 equirect, 1:1 spheremap)")
        ->check(CLI::IsMember({"equirect", "spheremap", "angmap", "angular"}));
    cmd->add_option("--env-rotation", opt.env_rotation, "Environment rotation about +y in degrees");
    cmd->add_option("--env-intensity", opt.env_intensity, "Environment radiance scale")->check(CLI::NonNegativeNumber);
}

}  // namespace glint::app
