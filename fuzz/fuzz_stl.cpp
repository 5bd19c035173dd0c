/// \file Fuzz target: an STL file, ASCII or binary, loaded as a bare mesh scene and rendered.

#include "fuzz_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const glint::fuzz::ScratchFolder folder;
    glint::fuzz::load_and_render(folder.write("model.stl", glint::fuzz::as_text(data, size)));
    return 0;
}
