// Using Glint as a library: build a scene in code, render it, save it.
//
//   ./build/examples/build_scene [output.png]
//
// The same steps as the seminar's main(): create materials, shapes and lights, set up the
// camera, prepare the scene (builds the acceleration structures), run the Whitted
// integrator into a film, and save the film as an image.

#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/image/image_io.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene/render_scene.h"

#include <cstdio>
#include <exception>
#include <memory>

int main(int argc, char** argv) {
    using namespace glint;
    const char* output = argc > 1 ? argv[1] : "build_scene.png";
    try {
        Scene scene;
        scene.camera = Camera::perspective({0, 3, 8}, {0, 1, 0}, {0, 1, 0}, 40.0f);
        scene.background = Background::constant(Color(0.6f, 0.75f, 0.95f));
        scene.ambient_light = Color(0.1f);

        // Materials: a red Lambertian ball, a mirror, glass, and a checkered floor.
        Material red;
        red.diffuse = Color(0.8f, 0.1f, 0.1f);
        red.ambient = red.diffuse;
        red.specular = Color(0.4f);  // Blinn-Phong highlight
        red.shininess = 50.0f;
        Material mirror;
        mirror.diffuse = Color(0.0f);
        mirror.reflectivity = Color(0.9f);
        Material glass;
        glass.diffuse = Color(0.0f);
        glass.transparency = 1.0f;  // all light through the Fresnel-weighted dielectric part
        glass.ior = 1.5f;
        Material floor;
        floor.diffuse = Color(1.0f);
        floor.ambient = Color(1.0f);
        floor.texture = scene.add_texture(std::make_unique<CheckerTexture>(Color(0.8f), Color(0.2f), 10.0f));

        scene.add_object(std::make_shared<Sphere>(Vec3(-1.6f, 1, 0), 1.0f), scene.add_material(red));
        scene.add_object(std::make_shared<Sphere>(Vec3(0.6f, 1, -1.5f), 1.0f), scene.add_material(mirror));
        scene.add_object(std::make_shared<Sphere>(Vec3(1.2f, 0.7f, 1.2f), 0.7f), scene.add_material(glass));
        scene.add_object(std::make_shared<Quad>(Vec3(-10, 0, 10), Vec3(20, 0, 0), Vec3(0, 0, -20)),
                         scene.add_material(floor));

        // A point light whose strength does not fall off with distance, as in the assignments.
        scene.add_light(std::make_unique<PointLight>(Vec3(4, 8, 6), Color(0.9f), Falloff::None));

        // Build the acceleration structures and lights; the description is kept read-only.
        const RenderScene prepared(std::move(scene));

        RenderSettings settings;
        settings.width = 480;
        settings.height = 320;
        settings.samples_per_axis = 2;  // 2×2 stratified samples per pixel
        Film film(settings.width, settings.height);
        const RenderStats stats = WhittedIntegrator(settings.max_depth).render(prepared, settings, film);

        write_image(output, film.to_image());
        std::printf("%s: %.2f M rays in %.2f s\n", output, double(stats.rays) * 1e-6, stats.seconds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "build_scene: %s\n", e.what());
        return 1;
    }
    return 0;
}
