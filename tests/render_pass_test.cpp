// Progressive rendering (Integrator::render_pass, the viewer's): N² passes in order make the
// film that render() makes, bit for bit, whatever the thread count; a stop ends a pass early.
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/default_scene.h"
#include "glint/scene/render_scene.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>

namespace {

bool same_film(const glint::Film& a, const glint::Film& b) {
    return a.pixels().size() == b.pixels().size() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size_bytes()) == 0;
}

}  // namespace

TEST(RenderPass, AllPassesInOrderMakeTheRenderedFilm) {
    const glint::RenderScene scene(glint::make_spheres_scene());
    for (const char* integrator : {"whitted", "path"}) {
        glint::RenderSettings s;
        s.width = 48;
        s.height = 36;
        s.samples_per_axis = 3;
        s.integrator = integrator;
        s.filter = glint::PixelFilter::Mitchell;
        const auto renderer = glint::make_integrator(s);
        glint::Film rendered(s.width, s.height);
        (void)renderer->render(scene, s, rendered);
        for (const uint32_t threads : {1u, 2u}) {
            s.threads = threads;
            glint::Film progressive(s.width, s.height);
            for (uint32_t pass = 0; pass < 9; ++pass) {
                const glint::RenderStats stats = renderer->render_pass(scene, scene.camera(), s, progressive, pass);
                EXPECT_TRUE(stats.complete());
                EXPECT_GT(stats.rays, 0u);
                if (pass < 8) {
                    EXPECT_FALSE(same_film(progressive, rendered));
                }
            }
            EXPECT_TRUE(same_film(progressive, rendered)) << integrator << ", " << threads << " threads";
        }
    }
}

TEST(RenderPass, AStopEndsThePassAndABadIndexIsRefused) {
    const glint::RenderScene scene(glint::make_spheres_scene());
    glint::RenderSettings s;
    s.width = 32;
    s.height = 32;
    const auto renderer = glint::make_integrator(s);
    glint::Film film(s.width, s.height);
    const std::atomic<bool> stop{true};
    const glint::RenderStats stats = renderer->render_pass(scene, scene.camera(), s, film, 0, &stop);
    EXPECT_EQ(stats.tiles_done, 0u);
    EXPECT_FALSE(stats.complete());
    EXPECT_THROW((void)renderer->render_pass(scene, scene.camera(), s, film, 1), std::out_of_range);
}
