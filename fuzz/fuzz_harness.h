#pragma once
/// \file What every fuzz target shares: a private folder to put the input in (the loaders
/// read files, as users' scenes are files), and the pipeline `glint render` runs on it.
///
/// The contract under test (docs/robustness.md): whatever the bytes, loading ends in a
/// scene or in a SceneError/ImageError; a loaded scene builds and renders. Anything else
/// (a crash, a sanitizer report, another exception, a hang) is a finding.

#include "glint/scene_file.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace glint::fuzz {

/// A fresh folder under the temporary directory (tmpfs /dev/shm when there is one),
/// removed with everything in it when the object dies.
class ScratchFolder {
public:
    ScratchFolder();
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    /// Write `bytes` to the file `name` in the folder; returns its path.
    std::filesystem::path write(std::string_view name, std::string_view bytes) const;
    /// A symbolic link `name` in the folder to `target` (assets the input may refer to).
    void link(std::string_view name, const std::filesystem::path& target) const;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

/// The fuzzer's bytes as text.
[[nodiscard]] inline std::string_view as_text(const uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

/// Load `scene_file` as `glint render` does, build its render scene and render a few
/// pixels at one sample with one thread. Returns normally when the loader refuses the file
/// with a SceneError or ImageError (the errors it promises). With `options.shutter`, the
/// camera gets that shutter too, as with --shutter.
void load_and_render(const std::filesystem::path& scene_file, const SceneFileOptions& options = {});

/// The repository's folder (compiled in): example assets that fuzzed scenes may refer to.
[[nodiscard]] std::filesystem::path source_dir();

}  // namespace glint::fuzz
