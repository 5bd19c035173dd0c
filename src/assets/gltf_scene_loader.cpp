#include "glint/assets/gltf_scene_loader.h"

#include "gltf_document.h"
#include "gltf_materials.h"
#include "gltf_motion.h"
#include "import_notes.h"
#include "mesh_file.h"
#include "place_meshes.h"

#include "glint/diagnostics.h"
#include "glint/math/constants.h"
#include "glint/scene/asset_defaults.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint {

namespace {

/// A node's frame, for placing a camera or a light with point() and vector(). Unlike a
/// mesh, a light still has a place under a singular node (scale 0: glTF lights ignore the
/// node's scale), so the inverse, which nothing here reads, falls back to the identity
/// instead of refusing the node.
Transform node_frame(const Matrix4& world_from_node) {
    Matrix4 inverse;
    if (!world_from_node.inverse(inverse)) inverse = Matrix4::identity();
    return {world_from_node, inverse};
}

/// Extensions the loader maps (fully or in part); anything else in extensionsUsed is reported.
bool is_mapped_extension(const std::string& name) {
    return name == "KHR_lights_punctual" || gltf::is_mapped_material_extension(name);
}

/// glTF cameras look along their node's -z with +y up.
void collect_cameras(const gltf::Document& doc, const std::vector<gltf::PlacedNode>& nodes, GltfReport& report,
                     ImportNotes& notes) {
    const auto& json = doc.json;
    for (const gltf::PlacedNode& placed : nodes) {
        const auto& node = json.at("nodes").at(std::size_t(placed.node));
        if (!node.contains("camera")) continue;
        const auto index = gltf::integer<std::size_t>(node.at("camera"));
        if (index >= gltf::array_size(json, "cameras")) continue;
        const auto& cam = json.at("cameras").at(index);
        const Transform frame = node_frame(placed.world_from_node);
        const Vec3 eye = frame.point(Vec3(0.0f));
        const Vec3 forward = frame.vector(Vec3(0.0f, 0.0f, -1.0f));
        const Vec3 up = frame.vector(Vec3(0.0f, 1.0f, 0.0f));
        GltfCamera result;
        result.index = int(index);
        result.node = placed.node;
        result.name = cam.value("name", node.value("name", "camera" + std::to_string(index)));
        try {
            if (cam.value("type", "") == "orthographic") {
                const auto& o = cam.at("orthographic");
                result.camera = Camera::orthographic(eye, eye + forward, up, 2.0f * o.at("ymag").get<float>());
                const float ymag = o.at("ymag").get<float>();
                result.aspect = ymag > 0.0f ? o.at("xmag").get<float>() / ymag : 0.0f;
            } else {
                const auto& p = cam.at("perspective");
                result.camera = Camera::perspective(eye, eye + forward, up, degrees(p.at("yfov").get<float>()));
                result.aspect = p.value("aspectRatio", 0.0f);
            }
        } catch (const std::invalid_argument& e) {
            notes.ignored(std::string("camera with unusable parameters (") + e.what() + ")", result.name);
            continue;
        }
        report.cameras.push_back(std::move(result));
    }
}

/// KHR_lights_punctual to Glint lights: intensities divided by π (docs/units.md).
void collect_lights(const gltf::Document& doc, const std::vector<gltf::PlacedNode>& nodes, Scene& scene,
                    GltfReport& report, ImportNotes& notes) {
    const auto& json = doc.json;
    if (!json.contains("extensions") || !json.at("extensions").contains("KHR_lights_punctual")) return;
    const auto& lights = json.at("extensions").at("KHR_lights_punctual").value("lights", nlohmann::json::array());
    for (const gltf::PlacedNode& placed : nodes) {
        const auto& node = json.at("nodes").at(std::size_t(placed.node));
        if (!node.contains("extensions") || !node.at("extensions").contains("KHR_lights_punctual")) continue;
        const auto index =
            gltf::integer_or<std::size_t>(node.at("extensions").at("KHR_lights_punctual"), "light", std::size_t(-1));
        if (index >= lights.size()) continue;
        const auto& light = lights[index];
        const std::string name = light.value("name", "light" + std::to_string(index));
        Color color(1.0f);
        if (light.contains("color") && light.at("color").size() >= 3)
            color = {light.at("color").at(0).get<float>(), light.at("color").at(1).get<float>(),
                     light.at("color").at(2).get<float>()};
        const Color glint_intensity = color * (light.value("intensity", 1.0f) * kInvPi);
        const Transform frame = node_frame(placed.world_from_node);
        const Vec3 position = frame.point(Vec3(0.0f));
        const Vec3 direction = frame.vector(Vec3(0.0f, 0.0f, -1.0f));
        const std::string type = light.value("type", "");
        if (light.contains("range")) notes.ignored("light range (inverse-square falloff has no cut-off)", name);
        try {
            if (type == "point") {
                scene.add_light(std::make_unique<PointLight>(position, glint_intensity, Falloff::InverseSquare));
            } else if (type == "spot") {
                const auto spot = light.value("spot", nlohmann::json::object());
                const float outer = std::clamp(spot.value("outerConeAngle", kPi / 4.0f), 0.0f, kPi / 2.0f);
                const float inner = std::clamp(spot.value("innerConeAngle", 0.0f), 0.0f, outer);
                scene.add_light(std::make_unique<SpotLight>(position, direction, glint_intensity, inner, outer,
                                                            Falloff::InverseSquare));
            } else if (type == "directional") {
                scene.add_light(std::make_unique<DirectionalLight>(direction, glint_intensity));
            } else {
                notes.ignored("light of unknown type '" + type + "'", name);
                continue;
            }
        } catch (const std::invalid_argument& e) {
            notes.ignored(std::string("light with unusable parameters (") + e.what() + ")", name);
            continue;
        }
        ++report.lights;
    }
}

/// Skins, morph targets and (unless a shutter poses the nodes) animations: the geometry
/// reader never sees them (it is given the geometry only), so they are reported from the JSON.
void note_animation(const gltf::Document& doc, const std::vector<gltf::PlacedNode>& nodes, bool posed,
                    ImportNotes& notes) {
    const auto& json = doc.json;
    for (const gltf::PlacedNode& placed : nodes) {
        const auto& node = json.at("nodes").at(std::size_t(placed.node));
        if (node.contains("skin"))
            notes.ignored("skin (mesh drawn in its bind pose)",
                          node.value("name", "node" + std::to_string(placed.node)));
    }
    std::size_t m = 0;
    for (const auto& mesh : json.value("meshes", nlohmann::json::array())) {
        for (const auto& primitive : mesh.value("primitives", nlohmann::json::array()))
            if (primitive.contains("targets")) {
                notes.ignored("morph targets (base shape drawn)", mesh.value("name", "mesh" + std::to_string(m)));
                break;
            }
        ++m;
    }
    if (const std::size_t animations = gltf::array_size(json, "animations"); animations > 0 && !posed)
        notes.ignored(std::to_string(animations) + " animation(s) (nodes drawn at their rest transforms)", "");
}

/// What the shutter did with the file's animations.
void note_shutter(const gltf::NodeAnimation& animation, const std::optional<gltf::NodeMotion>& motion,
                  const Shutter& shutter, ImportNotes& notes) {
    const std::size_t count = animation.animation_count();
    if (count == 0) return;
    const std::string animations = std::to_string(count) + " animation(s)";
    if (!motion) {
        notes.mapped(animations + ": no channel moves a node");
    } else if (shutter.close > shutter.open) {
        notes.mapped(fmt::format("{} sampled over the shutter [{}, {}] at {} time(s){}", animations, shutter.open,
                                 shutter.close, motion->times().size(),
                                 motion->thinned() ? " (evenly: more key times than that in the shutter)" : ""));
    } else {
        notes.mapped(fmt::format("{} posed at time {}", animations, shutter.open));
    }
}

/// Cameras and lights are placed where their nodes are at the shutter's open time: a glTF
/// camera's motion (not turned into Camera keys, which move the eye and target on straight
/// lines) and moving lights (light sampling assumes lights stay put) are not blurred.
void note_posed_camera_and_lights(const gltf::Document& doc, const gltf::NodeMotion& motion, const GltfReport& report,
                                  ImportNotes& notes) {
    const std::vector<gltf::PlacedNode>& nodes = motion.at_open();
    for (std::size_t p = 0; p < nodes.size(); ++p) {
        if (!motion.moves(p)) continue;
        const auto& node = doc.json.at("nodes").at(std::size_t(nodes[p].node));
        const std::string name = node.value("name", "node" + std::to_string(nodes[p].node));
        if (report.selected_camera >= 0 && report.cameras[std::size_t(report.selected_camera)].node == nodes[p].node)
            notes.ignored("camera animation blur (the camera is placed where it is at the shutter's open time)", name);
        if (node.contains("extensions") && node.at("extensions").contains("KHR_lights_punctual"))
            notes.ignored("light animation (the light is placed where it is at the shutter's open time)", name);
    }
}

int find_camera(const GltfReport& report, const std::string& wanted) {
    if (report.cameras.empty()) return -1;
    if (wanted.empty()) return 0;
    for (std::size_t i = 0; i < report.cameras.size(); ++i)
        if (report.cameras[i].name == wanted) return int(i);
    const bool numeric = wanted.find_first_not_of("0123456789") == std::string::npos;
    if (numeric)
        for (std::size_t i = 0; i < report.cameras.size(); ++i)
            if (report.cameras[i].index == std::stoi(wanted)) return int(i);
    return -2;
}

/// Render through the file's camera `options.camera` (the first by default), or frame the
/// scene automatically when the file has none; the image gets the camera's aspect ratio.
void choose_camera(const std::filesystem::path& path, const GltfOptions& options, GltfReport& report, Scene& scene,
                   RenderSettings& settings, ImportNotes& notes) {
    settings.width = 640;
    settings.height = 480;
    report.selected_camera = find_camera(report, options.camera);
    if (report.selected_camera == -2) {
        std::string names;
        for (const GltfCamera& c : report.cameras)
            names += (names.empty() ? "" : ", ") + std::to_string(c.index) + " '" + c.name + "'";
        throw SceneError(path.string() + ": no camera '" + options.camera + "' (the file has " +
                         (names.empty() ? std::string("none") : names) + ")");
    }
    if (report.selected_camera >= 0) {
        const GltfCamera& chosen = report.cameras[std::size_t(report.selected_camera)];
        scene.camera = chosen.camera;
        if (chosen.aspect > 0.0f)
            settings.height = std::max(1u, uint32_t(std::lround(float(settings.width) / chosen.aspect)));
        notes.mapped("camera: '" + chosen.name + "' (" + std::to_string(report.cameras.size()) + " in the file)");
    } else {
        scene.camera =
            framing_camera(scene.world_bounds(), float(settings.width) / float(settings.height), path, options.up);
        notes.mapped("camera: none in the file; automatic camera framing the scene's bounds");
    }
}

GltfScene load(const std::filesystem::path& path, const GltfOptions& options) {
    GltfScene result;
    Scene& scene = result.loaded.scene;
    GltfReport& report = result.report;
    ImportNotes notes;

    const gltf::Document doc = gltf::read_document(path);
    MeshFile file = read_gltf_geometry(doc);
    for (std::string& w : file.warnings) result.loaded.warnings.push_back(std::move(w));

    // With a shutter, the nodes are posed by the file's animations (gltf_motion.h).
    std::optional<gltf::NodeMotion> motion;
    if (options.shutter) {
        const gltf::NodeAnimation animation(doc, notes);
        if (animation.moves_nodes()) motion.emplace(doc, animation, *options.shutter);
        note_shutter(animation, motion, *options.shutter, notes);
    }
    const std::vector<gltf::PlacedNode> nodes = motion ? motion->at_open() : gltf::placed_nodes(doc);
    note_animation(doc, nodes, options.shutter.has_value(), notes);
    const std::size_t gpu_instances = file.gpu_instances;
    if (gpu_instances > 0)
        notes.mapped("EXT_mesh_gpu_instancing: " + std::to_string(gpu_instances) + " instance(s) placed");

    gltf::MaterialConverter materials(doc, scene, notes);
    materials.convert_all();
    report.materials = gltf::array_size(doc.json, "materials");

    auto material = [&](uint32_t mesh) {
        const uint32_t file_material = file.mesh_materials[mesh];
        if (file_material >= report.materials) report.default_material = true;
        const gltf::MaterialInfo& info = materials.material(int(file_material));
        if (info.alpha_mask) file.meshes[mesh]->set_alpha_mask(info.alpha_mask, info.alpha_cutoff);
        return info.scene_material;
    };
    std::size_t moving = 0;
    const PlacedMeshes placed = motion
                                    ? gltf::place_posed_meshes(scene, doc, file, *motion, material, notes, moving)
                                    : place_meshes(scene, file.placements, file.meshes, Transform(), material, notes);
    if (moving > 0) notes.mapped("animation: " + std::to_string(moving) + " object(s) move while the shutter is open");
    report.objects = placed.objects;
    report.instanced_triangles = placed.instanced_triangles;
    for (const TriangleMesh* mesh : placed.meshes) report.triangles += mesh->triangle_count();
    if (report.objects == 0) throw SceneError(path.string() + ": no mesh can be placed (every node was skipped)");
    report.primitives = placed.meshes.size();
    report.meshes = file.distinct_meshes;
    report.textures = materials.texture_count();

    collect_cameras(doc, nodes, report, notes);
    collect_lights(doc, nodes, scene, report, notes);

    choose_camera(path, options, report, scene, result.loaded.settings, notes);
    if (motion) note_posed_camera_and_lights(doc, *motion, report, notes);
    if (report.lights == 0) {
        add_default_lighting(scene);
        report.default_lighting = true;
        notes.mapped("lights: none in the file; default key light + uniform grey environment (docs/assets.md)");
    } else {
        notes.mapped("lights: " + std::to_string(report.lights) + " KHR_lights_punctual light(s), intensity / pi");
    }

    // glTF is in physical units (lux, candela, nits): sunlit surfaces and visible lamps go
    // far past display white, so PNG/JPEG output is tone mapped as the Khronos glTF Sample
    // Viewer does by default, at the file's own exposure.
    result.loaded.display = DisplayTransform{ToneCurve::PbrNeutral, Exposure{}};
    notes.mapped("display: pbr-neutral tone curve for PNG/JPEG (--tonemap, --exposure)");

    std::size_t single_sided = 0;
    for (std::size_t m = 0; m < report.materials; ++m)
        if (!materials.material(int(m)).double_sided) ++single_sided;
    notes.mapped("materials: " + std::to_string(report.materials) + " converted" +
                 (report.default_material ? " (+ the glTF default material)" : "") + ", " +
                 std::to_string(report.textures) + " texture(s)");
    if (const std::size_t views = materials.transformed_view_count(); views > 0)
        notes.mapped("KHR_texture_transform: " + std::to_string(views) + " texture(s) seen through a uv transform");
    if (single_sided > 0)
        notes.mapped("doubleSided: " + std::to_string(single_sided) +
                     " single-sided material(s) drawn two-sided (no back-face culling; exact for closed meshes)");
    notes.mapped("meshes: " + std::to_string(report.meshes) + " (" + std::to_string(report.primitives) +
                 " primitives) placed " + std::to_string(report.objects) + " time(s)");

    for (const auto& ext : doc.json.value("extensionsUsed", nlohmann::json::array())) {
        const std::string name = ext.get<std::string>();
        if (is_mapped_extension(name) || notes.has("material extension " + name)) continue;
        if (name == "EXT_mesh_gpu_instancing" && gpu_instances > 0) continue;
        notes.ignored("extension " + name, "");
    }
    report.mapped = notes.mapped_lines();
    report.ignored = notes.ignored_lines();
    for (const std::string& line : report.ignored)
        result.loaded.warnings.push_back(path.string() + ": ignored " + line);
    return result;
}

}  // namespace

GltfScene load_gltf_scene(const std::filesystem::path& path, const GltfOptions& options) {
    try {
        return load(path, options);
    } catch (const nlohmann::json::exception& e) {
        // A structurally broken file (wrong types, dangling indices) the checks above missed.
        throw SceneError(path.string() + ": malformed glTF: " + gltf::json_error_text(e));
    }
}

}  // namespace glint
