#include "glint/scene_format/scene_builder.h"

#include "object_builder.h"

#include "glint/assets/mesh_loader.h"
#include "glint/image/filter.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/materials/uv_transform_texture.h"
#include "glint/scene/environment.h"
#include "glint/scene_format/build_context.h"
#include "glint/scene_format/registry.h"

#include "glint/scene_format/did_you_mean.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include <array>

namespace glint {

namespace {

constexpr std::array<std::string_view, 2> kProjections{"perspective", "orthographic"};
constexpr std::array<std::string_view, 4> kBackgrounds{"color", "spheremap", "equirect", "angmap"};
constexpr std::array<std::string_view, 2> kShadowModes{"none", "opaque"};

/// An integer from `min` to `max`.
uint32_t count(const ParamTable& t, std::string_view key, int64_t fallback, int64_t min, int64_t max) {
    const int64_t n = t.integer(key, fallback);
    if (n < min || n > max) t.fail(key, fmt::format("an integer from {} to {}", min, max));
    return static_cast<uint32_t>(n);
}

/// `aovs = ["albedo", ...]`: names from aov_names(); one named twice is taken once.
std::vector<Aov> read_aovs(const ParamTable& t) {
    std::vector<Aov> aovs;
    const ParamValue* list = t.find("aovs");
    if (!list) return aovs;
    const ParamValue::Array& names = list->as_array(t.name_of("aovs"));
    const std::vector<std::string> known(aov_names().begin(), aov_names().end());
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string what = fmt::format("{}[{}]", t.name_of("aovs"), i);
        const std::string& name = names[i].as_string(what);
        const std::optional<Aov> aov = aov_from_name(name);
        if (!aov) names[i].fail(what, fmt::format("one of {}{}", fmt::join(known, ", "), did_you_mean(name, known)));
        if (std::find(aovs.begin(), aovs.end(), *aov) == aovs.end()) aovs.push_back(*aov);
    }
    return aovs;
}

/// `adaptive = { min_spp, max_spp, threshold }` (integrators/adaptive_sampling.h).
void read_adaptive(const ParamTable& t, RenderSettings& s) {
    const uint32_t max_spp = count(t, "max_spp", 64, 1, SettingLimits::kMaxSpp);
    if (!is_power_of_four(max_spp))
        t.fail("max_spp",
               "a power of 4 (4, 16, 64, 256, 1024, 4096): adaptive samples are taken in a stratified order");
    s.samples_per_axis = *samples_per_axis(max_spp);
    AdaptiveSampling adaptive;
    adaptive.min_spp = count(t, "min_spp", std::min<int64_t>(4, max_spp), 1, max_spp);
    adaptive.threshold = t.number("threshold", adaptive.threshold);
    if (!(adaptive.threshold > 0.0f)) t.fail("threshold", "a positive relative error (0.01: 1 %)");
    t.reject_unknown_keys();
    s.adaptive = adaptive;
}

void read_render(const ParamTable& t, RenderSettings& s) {
    s.width = count(t, "width", s.width, 1, SettingLimits::kMaxImageSide);
    s.height = count(t, "height", s.height, 1, SettingLimits::kMaxImageSide);
    // Samples per pixel, as on the command line: N² for N×N stratified samples.
    const std::optional<uint32_t> n = samples_per_axis(count(t, "spp", 1, 1, SettingLimits::kMaxSpp));
    if (!n)
        t.fail("spp", "a square number of samples per pixel (1, 4, 9, 16, ...): Glint takes N×N stratified samples");
    s.samples_per_axis = *n;
    s.max_depth = count(t, "max_depth", s.max_depth, 0, SettingLimits::kMaxDepth);
    const int64_t seed = t.integer("seed", 0);
    if (seed < 0) t.fail("seed", "a non-negative integer");
    s.seed = static_cast<uint64_t>(seed);
    s.filter = *filter_from_name(t.choice("filter", filter_names(), "box"));
    if (t.find("filter_radius")) {
        s.filter_radius = t.number("filter_radius", 0.0f);
        if (!(s.filter_radius > 0.0f && s.filter_radius <= SettingLimits::kMaxFilterRadius))
            t.fail("filter_radius", "a filter radius in pixels, above 0 and at most 16");
    }
    const std::vector<std::string_view> integrators = integrator_names();
    s.integrator = t.choice("integrator", integrators, s.integrator);
    s.light_samples = count(t, "light_samples", s.light_samples, 1, SettingLimits::kMaxLightSamples);
    s.glossy_samples = count(t, "glossy_samples", s.glossy_samples, 1, SettingLimits::kMaxGlossySamples);
    s.mis = *mis_heuristic_from_name(t.choice("mis", mis_heuristic_names(), "power"));
    s.aovs = read_aovs(t);
    if (const ParamTable* adaptive = t.table("adaptive")) {
        if (t.find("spp"))
            t.fail("spp", "spp or adaptive.max_spp, not both: with adaptive sampling max_spp is the most");
        read_adaptive(*adaptive, s);
    }
    t.reject_unknown_keys();
}

/// `[display]`: how PNG/JPEG output is exposed and tone mapped (docs/scene-format.md).
DisplayTransform read_display(const ParamTable& t) {
    DisplayTransform display;
    constexpr std::array<std::string_view, 5> kCurves = {"none", "clamp", "aces", "agx", "pbr-neutral"};
    display.tone_curve = *parse_tone_curve(t.choice("tonemap", kCurves, "none"));
    if (const ParamValue* exposure = t.find("exposure")) {
        if (exposure->is_number())
            display.exposure.stops = exposure->as_float("display.exposure");
        else if (exposure->is_string() && exposure->as_string("display.exposure") == "auto")
            display.exposure.automatic = true;
        else
            t.fail("exposure", "a number of stops or \"auto\"");
    }
    t.reject_unknown_keys();
    return display;
}

/// The 35 mm film format's height, for an f-number given without a focal length.
constexpr float kFullFrameHeightMm = 24.0f;

/// The `[camera]` lens keys (docs/scene-format.md): `aperture_radius` in world units, or
/// `f_stop` with `focal_length` in millimetres (scene units taken as metres, as glTF's);
/// `focus_distance` defaults to the distance to look_at. `vertical_fov` is 0 for an
/// orthographic camera, which then needs an explicit focal length for an f-number.
ThinLens read_lens(const ParamTable& t, float vertical_fov, float look_at_distance) {
    ThinLens lens;
    if (t.find("aperture_radius") && t.find("f_stop")) t.fail("f_stop", "either aperture_radius or f_stop, not both");
    if (t.find("aperture_radius")) {
        lens.aperture_radius = t.number("aperture_radius", 0.0f);
        if (!(lens.aperture_radius >= 0.0f)) t.fail("aperture_radius", "an aperture radius ≥ 0 in world units");
    }
    if (t.find("focal_length") && !t.find("f_stop")) t.fail("focal_length", "f_stop beside a focal length");
    if (t.find("f_stop")) {
        const float f_stop = t.number("f_stop", 0.0f);
        if (!(f_stop > 0.0f)) t.fail("f_stop", "a positive f-number (2.8, 8, ...)");
        float focal_mm = 0.0f;
        if (t.find("focal_length")) {
            focal_mm = t.number("focal_length", 0.0f);
            if (!(focal_mm > 0.0f)) t.fail("focal_length", "a positive focal length in millimetres");
        } else if (vertical_fov > 0.0f) {
            // The lens that gives this field of view on 35 mm film.
            focal_mm = 0.5f * kFullFrameHeightMm / std::tan(radians(vertical_fov) * 0.5f);
        } else {
            t.fail("f_stop", "aperture_radius, or focal_length beside f_stop: an orthographic camera has no fov");
        }
        lens.aperture_radius = 0.001f * focal_mm / (2.0f * f_stop);
    }
    lens.focus_distance = look_at_distance;  // zero when the camera is degenerate: Camera says so
    if (t.find("focus_distance")) {
        lens.focus_distance = t.number("focus_distance", 0.0f);
        if (!(lens.focus_distance > 0.0f)) t.fail("focus_distance", "a positive distance in world units");
    }
    lens.blades = count(t, "aperture_blades", 0, 0, ThinLens::kMaxBlades);
    if (!ThinLens::blades_allowed(lens.blades))
        t.fail("aperture_blades", fmt::format("0 for a round aperture, or 3 to {} blades", ThinLens::kMaxBlades));
    lens.rotation = t.number("aperture_rotation", 0.0f);
    return lens;
}

/// `[camera] shutter = [open, close]` in scene time (docs/scene-format.md, "Motion").
Shutter read_shutter(const ParamTable& t) {
    const ParamValue* v = t.find("shutter");
    if (!v) return {};
    const Vec2 times = v->as_vec2(t.name_of("shutter"));
    if (!(times.y >= times.x)) v->fail(t.name_of("shutter"), "[open, close] with close at or after open");
    return {times.x, times.y};
}

/// `[camera] motion = [{ time, position, look_at }, ...]`: two keys or more, in strictly
/// increasing time.
std::vector<Camera::Key> read_camera_keys(const ParamTable& t) {
    const ParamValue& motion = t.require("motion", "an array of { time, position, look_at }");
    const ParamValue::Array& elements = motion.as_array(t.name_of("motion"));
    if (elements.size() < 2) motion.fail(t.name_of("motion"), "two keys or more, { time, position, look_at }");
    std::vector<Camera::Key> keys;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const ParamTable& key = elements[i].as_table(ValueName(ValueName(t, "motion"), i));
        const float time = key.require_number("time");
        if (!keys.empty() && !(time > keys.back().time))
            key.fail("time", fmt::format("a time after the previous key's {}", keys.back().time));
        keys.push_back({time, key.require_vec3("position"), key.require_vec3("look_at")});
        key.reject_unknown_keys();
    }
    return keys;
}

Camera read_camera(const ParamTable& t) {
    const std::string type = t.choice("type", kProjections, "perspective");
    // A camera moved by keys is placed by them: its first key is where it starts.
    std::vector<Camera::Key> keys;
    if (t.find("motion")) {
        for (const std::string_view key : {"position", "look_at", "position_end", "look_at_end"})
            if (t.find(key))
                t.fail(key,
                       "no position, look_at, position_end or look_at_end beside motion (its keys place the camera)");
        keys = read_camera_keys(t);
    }
    const Vec3 position = keys.empty() ? t.require_vec3("position") : keys.front().eye;
    const Vec3 look_at = keys.empty() ? t.require_vec3("look_at") : keys.front().target;
    const Vec3 up = t.vec3("up", Vec3(0.0f, 1.0f, 0.0f));
    float size = 0.0f;
    if (type == "perspective") {
        size = t.number("fov", 52.0f);
        if (!(size > 0.0f && size < 180.0f)) t.fail("fov", "a vertical field of view between 0 and 180 degrees");
    } else {
        size = t.require_number("height");
        if (!(size > 0.0f)) t.fail("height", "a positive view height in world units");
    }
    const ThinLens lens = read_lens(t, type == "perspective" ? size : 0.0f, length(look_at - position));
    const Shutter shutter = read_shutter(t);
    // A moving camera: at position_end looking at look_at_end at time 1 (either defaults to
    // where the camera is at time 0).
    const bool moves = t.find("position_end") || t.find("look_at_end");
    const Vec3 position_end = t.vec3("position_end", position);
    const Vec3 look_at_end = t.vec3("look_at_end", look_at);
    t.reject_unknown_keys();
    Camera camera;
    try {
        camera = type == "perspective" ? Camera::perspective(position, look_at, up, size)
                                       : Camera::orthographic(position, look_at, up, size);
        camera.set_lens(lens);
        camera.set_shutter(shutter);
    } catch (const std::invalid_argument& e) {
        t.fail_here(
            fmt::format("camera: {}; expected distinct position and look_at and an up vector off the view "
                        "direction",
                        e.what()));
    }
    if (moves) keys = {{0.0f, position, look_at}, {1.0f, position_end, look_at_end}};
    if (!keys.empty()) {
        try {
            camera.set_motion(std::move(keys));
        } catch (const std::invalid_argument& e) {
            t.fail(t.find("motion")         ? "motion"
                   : t.find("position_end") ? "position_end"
                                            : "look_at_end",
                   fmt::format("a camera motion whose view stays defined ({})", e.what()));
        }
    }
    return camera;
}

Background read_background(const ParamTable& t, BuildContext& context) {
    const std::string type = t.choice("type", kBackgrounds, "color");
    if (type == "color") {
        const Color c = t.color("color", Color(0.0f));
        t.reject_unknown_keys();
        return Background::constant(c);
    }
    const BackgroundKind kind = *parse_environment_kind(type);
    auto image = context.image(t, "file", ColorEncoding::Color);
    if (const std::optional<std::string> problem = environment_shape_problem(kind, image->width, image->height))
        t.fail("file", *problem);
    const float rotation = t.number("rotation", 0.0f);
    const float intensity = t.number("intensity", 1.0f);
    if (intensity < 0.0f) t.fail("intensity", "a non-negative radiance scale");
    t.reject_unknown_keys();
    return Background::environment(kind, std::move(image), rotation, intensity);
}

void read_world(const ParamTable& t, Scene& scene) {
    scene.ambient_light = t.color("ambient_light", Color(0.0f));
    scene.ambient_ior = t.number("ambient_ior", 1.0f);
    if (!(scene.ambient_ior > 0.0f)) t.fail("ambient_ior", "a positive index of refraction");
    scene.dielectric_shadows = t.choice("dielectric_shadows", kShadowModes, "none") == "opaque"
                                   ? DielectricShadows::Opaque
                                   : DielectricShadows::None;
    scene.emission_lights = t.boolean("emission_lights", scene.emission_lights);
    scene.environment_lighting = t.boolean("environment_lighting", scene.environment_lighting);
    t.reject_unknown_keys();
}

void read_texture(const ParamTable& t, BuildContext& context) {
    const std::string& name = t.require_string("name");
    if (context.has_texture(name)) t.fail("name", "a name not used by an earlier texture");
    std::unique_ptr<Texture> texture = chosen_type(t, texture_types()).create(t, context);
    const Vec2 uv_scale = t.vec2("uv_scale", Vec2(1.0f, 1.0f));
    const Vec2 uv_offset = t.vec2("uv_offset", Vec2(0.0f, 0.0f));
    t.reject_unknown_keys();
    Scene& scene = context.scene();
    const Texture* added = scene.add_texture(std::move(texture));
    if (uv_scale != Vec2(1.0f, 1.0f) || uv_offset != Vec2(0.0f, 0.0f))
        added = scene.add_texture(std::make_unique<UvTransformTexture>(added, uv_scale, uv_offset));
    context.name_texture(name, added);
}

void read_material(const ParamTable& t, BuildContext& context) {
    const std::string& name = t.require_string("name");
    if (context.scene().find_material(name)) t.fail("name", "a name not used by an earlier material");
    Material m = chosen_type(t, material_types(), "standard").create(t, context);
    m.name = name;
    t.reject_unknown_keys();
    context.scene().add_material(std::move(m));
}

void read_light(const ParamTable& t, BuildContext& context) { chosen_type(t, light_types()).add(t, context); }

}  // namespace

LoadedScene build_scene(const ParamTable& root, const std::filesystem::path& base_dir,
                        const MoreObjects& more_objects) {
    LoadedScene out;
    MeshCache meshes;
    BuildContext context(base_dir, out.scene, meshes, out.warnings);
    // Look every section up first so that a misspelt section is reported before any work.
    const ParamTable* render = root.table("render");
    const ParamTable* display = root.table("display");
    const ParamTable* camera = root.table("camera");
    const ParamTable* background = root.table("background");
    const ParamTable* world = root.table("world");
    const auto textures = root.tables("textures");
    const auto materials = root.tables("materials");
    const auto lights = root.tables("lights");
    (void)root.find("shapes");
    (void)root.find("objects");
    root.reject_unknown_keys();

    if (render) read_render(*render, out.settings);
    if (display) out.display = read_display(*display);
    if (camera) out.scene.camera = read_camera(*camera);
    if (world) read_world(*world, out.scene);
    if (background) out.scene.background = read_background(*background, context);
    for (const ParamTable* t : textures) read_texture(*t, context);
    for (const ParamTable* t : materials) read_material(*t, context);
    for (const ParamTable* t : lights) read_light(*t, context);
    add_objects(root, more_objects, context);
    // Every builder rejected its own unknown keys; this catches tables none of them visited.
    root.reject_unknown_keys_recursive();
    // Legal but most likely not what was meant: the render would show only the background.
    const std::string file = root.where().file ? *root.where().file : std::string("<scene>");
    if (out.scene.objects().empty())
        out.warnings.push_back(file + ": the scene has no [[objects]]");
    else if (!out.scene.has_emitters() && out.scene.ambient_light.is_black())
        out.warnings.push_back(file +
                               ": the scene has no [[lights]] and no ambient light; only emission, "
                               "reflections and refractions of the background will show");
    return out;
}

}  // namespace glint
