#include "assemble_command.h"

#include "glint/image/frame_assembly.h"
#include "glint/image/image_io.h"

#include <fmt/core.h>

namespace glint::app {

void add_assemble_options(CLI::App* command, AssembleOptions& opt) {
    command->add_option("parts", opt.parts, "The crops: EXR files written by glint render --crop")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", opt.output, "The frame: .exr keeps every channel; other formats R, G, B")
        ->required();
}

int run_assemble(const AssembleOptions& opt) {
    glint::check_output_path(opt.output);
    std::vector<glint::FramePart> parts;
    parts.reserve(opt.parts.size());
    for (const std::string& path : opt.parts) {
        glint::Image image = glint::read_image(path, glint::ColorEncoding::Data);
        parts.push_back({path, std::move(image)});
    }
    const glint::Image frame = glint::assemble_frame(parts);
    glint::write_image(opt.output, frame);
    fmt::print("{} parts -> {}×{} {}\n", parts.size(), frame.width, frame.height, opt.output);
    return 0;
}

}  // namespace glint::app
