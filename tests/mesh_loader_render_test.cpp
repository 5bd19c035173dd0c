// Every Stanford mesh in shared/data renders as a scene of its own (framing camera, default
// lighting): a finite, non-blank image.

#include "glint/image/film.h"
#include "glint/integrators/whitted_integrator.h"
#include "glint/scene_file.h"
#include "glint/scene/render_scene.h"

#include "source_paths.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

TEST(MeshScenes, StanfordMeshesRenderFinite) {
    const std::filesystem::path dir = glint_test::kSharedMeshDir;
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no shared meshes at " << dir;
    for (const char* name : {"stanford_bunny.ply", "stanford_lucy_100k.ply", "stanford_dragon_res2.ply", "stanford_dragon.ply"}) {
        glint::LoadedScene loaded = glint::load_scene_file(dir / name).loaded;
        const glint::RenderScene prepared(std::move(loaded.scene));
        glint::RenderSettings settings;
        settings.width = 24;
        settings.height = 18;
        glint::Film film(settings.width, settings.height);
        glint::WhittedIntegrator(2).render(prepared, settings, film, {});
        float lo = 1e30f, hi = -1e30f;
        bool finite = true;
        for (uint32_t y = 0; y < film.height(); ++y)
            for (uint32_t x = 0; x < film.width(); ++x) {
                finite = finite && film.at(x, y).is_finite();
                lo = std::min(lo, film.at(x, y).luminance());
                hi = std::max(hi, film.at(x, y).luminance());
            }
        EXPECT_TRUE(finite) << name;
        EXPECT_GT(hi - lo, 0.05f) << name << ": the mesh is not visible against the sky";
    }
}

}  // namespace
