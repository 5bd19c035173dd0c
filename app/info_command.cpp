#include "info_command.h"

#include "timing.h"

#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/render_scene.h"

#include <fmt/core.h>

#include <map>
#include <set>

namespace glint::app {

namespace {

std::string megabytes(std::size_t bytes) { return fmt::format("{:.1f} MB", double(bytes) / (1024.0 * 1024.0)); }

std::size_t meshes_with_vertex_colors(const Scene& scene) {
    std::set<const TriangleMesh*> coloured;
    for (const SceneObject& object : scene.objects())
        if (const auto* mesh = dynamic_cast<const TriangleMesh*>(object.shape.get()); mesh && !mesh->data().colors.empty())
            coloured.insert(mesh);
    return coloured.size();
}

}  // namespace

int run_info(const std::string& path, const SceneOptions& opt) {
    const auto load_start = Clock::now();
    SceneSource source = load_scene(path, opt);
    const double load_seconds = seconds_since(load_start);
    const auto build_start = Clock::now();
    const RenderScene scene(std::move(source.loaded.scene));
    const double build_seconds = seconds_since(build_start);
    const SceneStatistics stats = scene.statistics();

    std::map<std::string, int> light_kinds;
    for (const Light* light : scene.all_lights()) ++light_kinds[std::string(light->type_name())];
    std::string lights;
    for (const auto& [kind, count] : light_kinds) lights += fmt::format("{}{} {}", lights.empty() ? "" : ", ", count, kind);

    fmt::print("file:        {}\n", path);
    fmt::print("objects:     {} ({} unique shapes)\n", stats.objects, stats.unique_shapes);
    fmt::print("triangles:   {} unique, {} instanced\n", stats.unique_triangles, stats.instanced_triangles);
    if (const std::size_t coloured = meshes_with_vertex_colors(scene.description()); coloured > 0)
        fmt::print("colours:     vertex colours on {} mesh(es), multiplying the base colour\n", coloured);
    fmt::print("materials:   {}\n", scene.description().materials().size());
    fmt::print("textures:    {}\n", scene.description().texture_count());
    fmt::print("lights:      {}{}{}\n", scene.all_lights().size(), lights.empty() ? "" : ": ", lights);
    if (source.gltf) {
        const GltfReport& r = *source.gltf;
        fmt::print("cameras:     {} in the file\n", r.cameras.size());
        for (std::size_t i = 0; i < r.cameras.size(); ++i) {
            const GltfCamera& c = r.cameras[i];
            const Camera& cam = c.camera;
            fmt::print("  {} #{} '{}' {} at ({:.4g}, {:.4g}, {:.4g}){}\n", int(i) == r.selected_camera ? "*" : " ",
                       c.index, c.name,
                       cam.projection() == Projection::Perspective
                           ? fmt::format("perspective yfov {:.4g} deg", cam.vertical_fov())
                           : fmt::format("orthographic height {:.4g}", cam.view_height()),
                       cam.eye().x, cam.eye().y, cam.eye().z,
                       c.aspect > 0.0f ? fmt::format(", aspect {:.4g}", c.aspect) : std::string());
        }
    }
    const Camera& cam = scene.camera();
    fmt::print("camera:      {} at ({:.4g}, {:.4g}, {:.4g}) looking ({:.3f}, {:.3f}, {:.3f})\n",
               cam.projection() == Projection::Perspective
                   ? fmt::format("perspective {:.4g} deg", cam.vertical_fov())
                   : fmt::format("orthographic {:.4g}", cam.view_height()),
               cam.eye().x, cam.eye().y, cam.eye().z, cam.forward().x, cam.forward().y, cam.forward().z);
    const Bounds3 b = scene.bounds();
    fmt::print("bounds:      ({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g})\n", b.lo.x, b.lo.y, b.lo.z, b.hi.x,
               b.hi.y, b.hi.z);
    fmt::print("memory:      {} (geometry + acceleration structures)\n", megabytes(stats.memory_bytes));
    fmt::print("image:       {}x{}\n", source.loaded.settings.width, source.loaded.settings.height);
    if (source.gltf) {
        const GltfReport& r = *source.gltf;
        fmt::print("glTF:        {} mesh(es), {} primitive(s), {} light(s), {} material(s)\n", r.meshes, r.primitives,
                   r.lights, r.materials);
        fmt::print("mapped:\n");
        for (const std::string& line : r.mapped) fmt::print("  {}\n", line);
        fmt::print("ignored:{}\n", r.ignored.empty() ? " nothing" : "");
        for (const std::string& line : r.ignored) fmt::print("  {}\n", line);
    }
    // Problems worked around (dropped triangles, unreadable textures); for glTF the
    // "ignored" lines above are also warnings and are not repeated.
    for (const std::string& w : source.loaded.warnings)
        if (!source.gltf || w.find(": ignored ") == std::string::npos) fmt::print("warning:     {}\n", w);
    fmt::print("load {:.2f} s, build {:.2f} s\n", load_seconds, build_seconds);
    return 0;
}


}  // namespace glint::app
