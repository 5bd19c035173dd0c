/// \file Fuzz target: a glTF 2.0 JSON file (.gltf), loaded as a whole scene and rendered.
/// Buffers and images come from data: URIs inside the input (the seeds embed theirs).

#include "fuzz_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const glint::fuzz::ScratchFolder folder;
    // A shutter, as --shutter 0,1 gives: node animations are read and sampled over it.
    glint::fuzz::load_and_render(folder.write("scene.gltf", glint::fuzz::as_text(data, size)),
                                 {.camera = {}, .shutter = glint::Shutter{0.0f, 1.0f}});
    return 0;
}
