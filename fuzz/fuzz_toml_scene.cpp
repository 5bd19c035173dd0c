/// \file Fuzz target: a TOML scene file (docs/scene-format.md), loaded and rendered. The
/// scene's folder links to the example assets, so fuzzed scenes reach real meshes, textures
/// and environments by the names the example scenes use ("assets/...").

#include "fuzz_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const glint::fuzz::ScratchFolder folder;
    folder.link("assets", glint::fuzz::source_dir() / "scenes" / "assets");
    folder.link("data", glint::fuzz::source_dir() / "tests" / "data");
    glint::fuzz::load_and_render(folder.write("scene.toml", glint::fuzz::as_text(data, size)));
    return 0;
}
