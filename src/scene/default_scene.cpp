#include "glint/scene/default_scene.h"

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"

#include <memory>

namespace glint {

Scene make_spheres_scene(bool refraction_variant) {
    Scene scene;  // its camera is Camera's default, the seminar's
    scene.background = Background::constant(Color(0.05f, 0.07f, 0.12f));
    scene.ambient_light = Color(0.1f);
    scene.dielectric_shadows = DielectricShadows::Opaque;

    // The seminar's three materials; reflectivity r takes its share from the diffuse part.
    const Color base[3] = {{0.9f, 0.15f, 0.1f}, {0.15f, 0.8f, 0.2f}, {0.15f, 0.3f, 0.9f}};
    uint32_t material[3];
    for (int i = 0; i < 3; ++i) {
        Material m;
        m.name = "material" + std::to_string(i);
        const float r = refraction_variant ? 0.0f : 0.3f;
        const float t = (refraction_variant && i == 1) ? 0.9f : 0.0f;
        m.diffuse = base[i] * (1.0f - r);
        m.ambient = m.diffuse;
        m.reflectivity = Color(r);
        m.transparency = t;
        m.ior = (refraction_variant && i == 1) ? 1.5f : 1.0f;
        m.specular = Color(0.3f);
        m.shininess = 60.0f;
        material[i] = scene.add_material(m);
    }
    Material floor;
    floor.name = "floor";
    floor.diffuse = Color(0.6f);
    floor.ambient = floor.diffuse;
    floor.reflectivity = Color(refraction_variant ? 0.0f : 0.2f);
    const uint32_t floor_material = scene.add_material(floor);

    scene.add_object(
        std::make_shared<Quad>(Vec3(-40.0f, 0.0f, 40.0f), Vec3(80.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, -80.0f)),
        floor_material, std::nullopt, "floor");
    // A 5×5 grid of spheres; one sphere shape, placed 25 times, shows instancing too.
    auto unit_sphere = std::make_shared<Sphere>(Vec3(0.0f), 1.0f);
    for (int i = -2; i <= 2; ++i) {
        for (int j = -2; j <= 2; ++j) {
            const float radius = (i == 0 && j == 0) ? 3.0f : 1.8f;
            const Transform place =
                Transform::translate(Vec3(6.0f * float(i), radius, 6.0f * float(j))) * Transform::scale(Vec3(radius));
            scene.add_object(unit_sphere, material[(i + j + 6) % 3], place);
        }
    }
    scene.add_light(std::make_unique<PointLight>(Vec3(10.0f, 30.0f, 20.0f), Color(0.7f), Falloff::None));
    scene.add_light(std::make_unique<PointLight>(Vec3(-25.0f, 20.0f, 5.0f), Color(0.35f, 0.35f, 0.45f), Falloff::None));
    return scene;
}

LoadedScene make_default_scene() {
    LoadedScene loaded;
    loaded.scene = make_spheres_scene();
    loaded.settings.samples_per_axis = 2;
    return loaded;
}

}  // namespace glint
