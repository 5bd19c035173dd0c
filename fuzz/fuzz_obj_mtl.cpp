/// \file Fuzz target: a Wavefront OBJ file with its MTL material library, loaded as a bare
/// mesh scene (framing camera, default lighting) and rendered. One input holds both files:
/// the OBJ text, then a line "# ---- model.mtl ----", then the MTL text.

#include "fuzz_harness.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    constexpr std::string_view kSeparator = "\n# ---- model.mtl ----\n";
    const std::string_view input = glint::fuzz::as_text(data, size);
    const std::size_t split = input.find(kSeparator);
    const glint::fuzz::ScratchFolder folder;
    if (split != std::string_view::npos) folder.write("model.mtl", input.substr(split + kSeparator.size()));
    glint::fuzz::load_and_render(folder.write("model.obj", input.substr(0, split)));
    return 0;
}
