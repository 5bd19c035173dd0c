#include "fuzz_harness.h"

#include "glint/diagnostics.h"
#include "glint/image/film.h"
#include "glint/image/image_io.h"
#include "glint/integrators/integrator.h"
#include "glint/integrators/integrator_registry.h"
#include "glint/scene/render_scene.h"
#include "glint/scene_file.h"

#include <tbb/global_control.h>

#include <unistd.h>
#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace glint::fuzz {

namespace {

std::filesystem::path temporary_root() {
    std::error_code ec;
    if (std::filesystem::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
    return std::filesystem::temp_directory_path();
}

}  // namespace

ScratchFolder::ScratchFolder() {
    std::string pattern = (temporary_root() / "glint-fuzz-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder " + pattern);
    path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

std::filesystem::path ScratchFolder::write(std::string_view name, std::string_view bytes) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) throw std::runtime_error("cannot write " + file.string());
    return file;
}

void ScratchFolder::link(std::string_view name, const std::filesystem::path& target) const {
    std::filesystem::create_directory_symlink(target, path_ / name);
}

void load_and_render(const std::filesystem::path& scene_file, const SceneFileOptions& options) {
    // No worker threads, ever: every assimp import forks (src/assets/isolated_import.h), and
    // clang 14's ASan allocator is not fork-safe; a TBB worker freeing memory as the next
    // input forked left the child waiting on that allocator's lock forever (timeouts in
    // fuzz_ply and fuzz_obj_mtl). Static, so that no worker starts between inputs either.
    static const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    LoadedScene loaded;
    try {
        loaded = std::move(load_scene_file(scene_file, options).loaded);
    } catch (const SceneError&) {
        return;
    } catch (const ImageError&) {
        return;
    }
    // A few pixels exercise the camera, every material and light the rays reach and the
    // integrator's recursion; the depth and light samples stay as the file asks (bounded
    // by the loader), the cost per input small.
    if (options.shutter) loaded.scene.camera.set_shutter(*options.shutter);
    RenderSettings& settings = loaded.settings;
    settings.width = std::min<uint32_t>(settings.width, 6);
    settings.height = std::min<uint32_t>(settings.height, 4);
    settings.samples_per_axis = 1;
    settings.light_samples = std::min<uint32_t>(settings.light_samples, 4);
    settings.threads = 1;
    const RenderScene scene(std::move(loaded.scene));
    const std::unique_ptr<Integrator> integrator = make_integrator(settings);
    Film film(settings.width, settings.height);
    integrator->render(scene, settings, film);
    (void)film.to_image();
}

std::filesystem::path source_dir() { return GLINT_SOURCE_DIR; }

}  // namespace glint::fuzz
