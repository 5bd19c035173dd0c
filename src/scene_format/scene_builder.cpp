#include "scene_builder.h"

#include "glint/image/filter.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator_registry.h"
#include "transform_params.h"
#include "glint/scene_format/did_you_mean.h"
#include "object_builder.h"
#include "glint/materials/uv_transform_texture.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace glint {

namespace {

constexpr std::array<std::string_view, 2> kMisHeuristics{"balance", "power"};
constexpr std::array<std::string_view, 2> kProjections{"perspective", "orthographic"};
constexpr std::array<std::string_view, 3> kBackgrounds{"color", "spheremap", "equirect"};
constexpr std::array<std::string_view, 2> kShadowModes{"none", "opaque"};
constexpr std::array<std::string_view, 2> kTextureTypes{"image", "checker"};
constexpr std::array<std::string_view, 2> kWrapModes{"repeat", "clamp"};
constexpr std::array<std::string_view, 2> kEncodings{"color", "data"};
constexpr std::array<std::string_view, 6> kLightTypes{"point", "directional", "spot", "sphere", "quad", "disk"};
constexpr std::array<std::string_view, 2> kFalloffs{"none", "inverse_square"};

/// Everything the sections share while the scene is built.
struct Builder {
    const std::filesystem::path& base_dir;
    LoadedScene& out;
    std::map<std::string, std::shared_ptr<const Image>> images;
    std::map<std::string, const Texture*> textures;

    /// Read an image once even if several textures or the background use it.
    std::shared_ptr<const Image> image(const ParamTable& t, std::string_view key, ColorEncoding encoding) {
        const std::filesystem::path path = resolve_input_file(t, key, base_dir);
        const std::string cache_key = path.string() + (encoding == ColorEncoding::Data ? "#data" : "#color");
        if (auto it = images.find(cache_key); it != images.end()) return it->second;
        try {
            auto img = std::make_shared<const Image>(read_image(path, encoding));
            images.emplace(cache_key, img);
            return img;
        } catch (const ImageError& e) {
            t.fail(key, fmt::format("a readable image ({})", e.what()));
        }
    }

    const Texture* texture(const ParamTable& t, std::string_view key) {
        const ParamValue* v = t.find(key);
        if (!v) return nullptr;
        const std::string& name = v->as_string(t.name_of(key));
        if (auto it = textures.find(name); it != textures.end()) return it->second;
        std::vector<std::string> names;
        for (const auto& entry : textures) names.push_back(entry.first);
        v->fail(t.name_of(key), "the name of a texture in [[textures]]" + did_you_mean(name, names));
    }
};

/// An integer from `min` to `max`.
uint32_t count(const ParamTable& t, std::string_view key, int64_t fallback, int64_t min, int64_t max) {
    const int64_t n = t.integer(key, fallback);
    if (n < min || n > max) t.fail(key, fmt::format("an integer from {} to {}", min, max));
    return static_cast<uint32_t>(n);
}

void read_render(const ParamTable& t, RenderSettings& s) {
    s.width = count(t, "width", s.width, 1, 16384);
    s.height = count(t, "height", s.height, 1, 16384);
    // Samples per pixel, as on the command line: N² for N×N stratified samples.
    const uint32_t spp = count(t, "spp", 1, 1, 4096);
    s.samples_per_axis = static_cast<uint32_t>(std::lround(std::sqrt(double(spp))));
    if (s.samples_per_axis * s.samples_per_axis != spp)
        t.fail("spp", "a square number of samples per pixel (1, 4, 9, 16, ...): Glint takes N×N stratified samples");
    s.max_depth = count(t, "max_depth", s.max_depth, 0, 64);
    const int64_t seed = t.integer("seed", 0);
    if (seed < 0) t.fail("seed", "a non-negative integer");
    s.seed = static_cast<uint64_t>(seed);
    s.filter = *filter_from_name(t.choice("filter", filter_names(), "box"));
    if (t.find("filter_radius")) {
        s.filter_radius = t.number("filter_radius", 0.0f);
        if (!(s.filter_radius > 0.0f && s.filter_radius <= 16.0f))
            t.fail("filter_radius", "a filter radius in pixels, above 0 and at most 16");
    }
    const std::vector<std::string_view> integrators = integrator_names();
    s.integrator = t.choice("integrator", integrators, s.integrator);
    s.light_samples = count(t, "light_samples", s.light_samples, 1, 1024);
    s.mis = t.choice("mis", kMisHeuristics, "power") == "balance" ? MisHeuristic::Balance : MisHeuristic::Power;
    t.reject_unknown_keys();
}

Camera read_camera(const ParamTable& t) {
    const std::string type = t.choice("type", kProjections, "perspective");
    const Vec3 position = t.require_vec3("position");
    const Vec3 look_at = t.require_vec3("look_at");
    const Vec3 up = t.vec3("up", Vec3(0.0f, 1.0f, 0.0f));
    float size = 0.0f;
    if (type == "perspective") {
        size = t.number("fov", 52.0f);
        if (!(size > 0.0f && size < 180.0f)) t.fail("fov", "a vertical field of view between 0 and 180 degrees");
    } else {
        size = t.require_number("height");
        if (!(size > 0.0f)) t.fail("height", "a positive view height in world units");
    }
    t.reject_unknown_keys();
    try {
        return type == "perspective" ? Camera::perspective(position, look_at, up, size)
                                     : Camera::orthographic(position, look_at, up, size);
    } catch (const std::invalid_argument& e) {
        t.fail_here(
            fmt::format("camera: {}; expected distinct position and look_at and an up vector off the view "
                        "direction",
                        e.what()));
    }
}

Background read_background(const ParamTable& t, Builder& b) {
    const std::string type = t.choice("type", kBackgrounds, "color");
    if (type == "color") {
        const Color c = t.color("color", Color(0.0f));
        t.reject_unknown_keys();
        return Background::constant(c);
    }
    auto image = b.image(t, "file", ColorEncoding::Color);
    const float rotation = t.number("rotation", 0.0f);
    const float intensity = t.number("intensity", 1.0f);
    if (intensity < 0.0f) t.fail("intensity", "a non-negative radiance scale");
    t.reject_unknown_keys();
    const BackgroundKind kind = type == "spheremap" ? BackgroundKind::SphereMap : BackgroundKind::Equirectangular;
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
    t.reject_unknown_keys();
}

void read_texture(const ParamTable& t, Builder& b) {
    const std::string& name = t.require_string("name");
    if (b.textures.count(name)) t.fail("name", "a name not used by an earlier texture");
    const std::string type = t.choice("type", kTextureTypes, "");
    std::unique_ptr<Texture> texture;
    if (type == "image") {
        const bool data = t.choice("encoding", kEncodings, "color") == "data";
        auto image = b.image(t, "file", data ? ColorEncoding::Data : ColorEncoding::Color);
        const WrapMode wrap = t.choice("wrap", kWrapModes, "repeat") == "clamp" ? WrapMode::Clamp : WrapMode::Repeat;
        texture = std::make_unique<ImageTexture>(std::move(image), wrap, t.color("tint", Color(1.0f)));
    } else {
        const float scale = t.number("scale", 1.0f);
        if (!(scale > 0.0f)) t.fail("scale", "a positive number of squares per unit of u and v");
        texture = std::make_unique<CheckerTexture>(t.color("even", Color(0.9f)), t.color("odd", Color(0.1f)), scale);
    }
    const Vec2 uv_scale = t.vec2("uv_scale", Vec2(1.0f, 1.0f));
    const Vec2 uv_offset = t.vec2("uv_offset", Vec2(0.0f, 0.0f));
    t.reject_unknown_keys();
    const Texture* added = b.out.scene.add_texture(std::move(texture));
    if (uv_scale != Vec2(1.0f, 1.0f) || uv_offset != Vec2(0.0f, 0.0f))
        added = b.out.scene.add_texture(std::make_unique<UvTransformTexture>(added, uv_scale, uv_offset));
    b.textures.emplace(name, added);
}

float unit_interval(const ParamTable& t, std::string_view key, float fallback, std::string_view what) {
    const float x = t.number(key, fallback);
    if (x < 0.0f || x > 1.0f) t.fail(key, fmt::format("{} from 0 to 1", what));
    return x;
}

void read_material(const ParamTable& t, Builder& b) {
    Material m;
    m.name = t.require_string("name");
    if (b.out.scene.find_material(m.name)) t.fail("name", "a name not used by an earlier material");
    m.ambient = t.color("ambient", m.ambient);
    m.diffuse = t.color("diffuse", m.diffuse);
    m.texture = b.texture(t, "texture");
    m.specular = t.color("specular", m.specular);
    m.shininess = t.number("shininess", m.shininess);
    if (m.shininess < 0.0f) t.fail("shininess", "a non-negative Blinn-Phong exponent");
    m.reflectivity = t.color("reflectivity", m.reflectivity);
    m.fresnel_mirror = t.boolean("fresnel_mirror", m.fresnel_mirror);
    m.emission = t.color("emission", m.emission);
    m.emission_texture = b.texture(t, "emission_texture");
    m.alpha_texture = b.texture(t, "alpha_texture");
    m.alpha_cutoff = unit_interval(t, "alpha_cutoff", m.alpha_cutoff, "a coverage threshold");
    m.roughness = unit_interval(t, "roughness", m.roughness, "a roughness");

    // Two ways to say "dielectric": the seminar's transparency + ior, or the handout's
    // refraction_index alone (0 = opaque, otherwise a clear dielectric of that index).
    const ParamValue* handout_ior = t.find("refraction_index");
    const ParamValue* transparency = t.find("transparency");
    const ParamValue* ior = t.find("ior");
    if (handout_ior) {
        if (transparency || ior)
            t.fail("refraction_index",
                   "either refraction_index (the handout's model) or transparency and ior, not both");
        const float n = handout_ior->as_float(t.name_of("refraction_index"));
        if (n < 0.0f) t.fail("refraction_index", "0 for an opaque material or a positive index of refraction");
        m.transparency = n > 0.0f ? 1.0f : 0.0f;
        if (n > 0.0f) m.ior = n;
    } else {
        m.transparency = unit_interval(t, "transparency", 0.0f, "a transparency");
        if (ior) {
            m.ior = ior->as_float(t.name_of("ior"));
            if (m.ior < 0.0f) t.fail("ior", "a positive index of refraction (or 0 for opaque)");
            if (m.ior == 0.0f && m.transparency > 0.0f)
                t.fail("ior", "a positive index of refraction for a transparent material (ior = 0 means opaque)");
            if (m.ior == 0.0f) m.ior = 1.0f;
        }
    }
    t.reject_unknown_keys();
    b.out.scene.add_material(std::move(m));
}

float degrees_in(const ParamTable& t, std::string_view key, float fallback, float max) {
    const float a = t.number(key, fallback);
    if (a < 0.0f || a > max) t.fail(key, fmt::format("an angle from 0 to {} degrees", max));
    return a;
}

/// A colour that is not black: a light that emits nothing is a mistake.
Color emission(const ParamTable& t, std::string_view key) {
    const Color c = t.color(key, Color(1.0f));
    if (c.is_black()) t.fail(key, "a colour with some positive component: a light that emits nothing lights nothing");
    return c;
}

/// `[[lights]]` of type sphere, quad or disk: a shape that emits `radiance` (nits).
void read_area_light(const ParamTable& t, const std::string& type, Builder& b) {
    const Color radiance = emission(t, "radiance");
    // A lamp disk faces down unless told otherwise; spheres are closed and emit outwards.
    std::shared_ptr<Shape> shape = read_simple_shape(t, type, Vec3(0.0f, -1.0f, 0.0f));
    const bool two_sided = type != "sphere" && t.boolean("two_sided", false);
    std::optional<Transform> transform;
    if (const ParamValue* v = t.find("transform")) transform = read_transform(*v, t.name_of("transform"));
    const std::string name = t.string("name", "");
    t.reject_unknown_keys();
    b.out.scene.add_area_light(std::move(shape), Emitter{radiance, two_sided}, transform, name);
}

void read_light(const ParamTable& t, Builder& b) {
    const std::string type = t.choice("type", kLightTypes, "");
    if (type == "sphere" || type == "quad" || type == "disk") return read_area_light(t, type, b);
    const Color intensity = emission(t, "intensity");
    std::unique_ptr<Light> light;
    if (type == "directional") {
        const Vec3 direction = t.require_vec3("direction");
        if (!(length(direction) > 0.0f)) t.fail("direction", "a non-zero direction");
        light = std::make_unique<DirectionalLight>(direction, intensity);
    } else {
        const Vec3 position = t.require_vec3("position");
        const Falloff falloff =
            t.choice("falloff", kFalloffs, "none") == "inverse_square" ? Falloff::InverseSquare : Falloff::None;
        if (type == "point") {
            light = std::make_unique<PointLight>(position, intensity, falloff);
        } else {
            const Vec3 direction = t.require_vec3("direction");
            if (!(length(direction) > 0.0f)) t.fail("direction", "a non-zero direction");
            const float outer = degrees_in(t, "outer_angle", 30.0f, 90.0f);
            const float inner = degrees_in(t, "inner_angle", outer, outer);
            light =
                std::make_unique<SpotLight>(position, direction, intensity, radians(inner), radians(outer), falloff);
        }
    }
    t.reject_unknown_keys();
    b.out.scene.add_light(std::move(light));
}

}  // namespace

std::filesystem::path resolve_input_file(const ParamTable& table, std::string_view key,
                                         const std::filesystem::path& base_dir) {
    const ParamValue& v = table.require(key, "a file name, relative to the scene file's folder");
    const std::filesystem::path name = v.as_string(table.name_of(key));
    const std::filesystem::path path = name.is_absolute() ? name : base_dir / name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        v.fail(table.name_of(key), fmt::format("an existing file (looked for {})", path.string()));
    return path;
}

LoadedScene build_scene(const ParamTable& root, const std::filesystem::path& base_dir) {
    LoadedScene out;
    Builder b{base_dir, out, {}, {}};
    // Look every section up first so that a misspelt section is reported before any work.
    const ParamTable* render = root.table("render");
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
    if (camera) out.scene.camera = read_camera(*camera);
    if (world) read_world(*world, out.scene);
    if (background) out.scene.background = read_background(*background, b);
    for (const ParamTable* t : textures) read_texture(*t, b);
    for (const ParamTable* t : materials) read_material(*t, b);
    for (const ParamTable* t : lights) read_light(*t, b);
    MeshCache meshes;
    add_objects(root, base_dir, out.scene, meshes, out.warnings);
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
