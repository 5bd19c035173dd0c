#include "program_beside.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <system_error>
#include <vector>

namespace glint::app {

std::string run_program_beside(const char* name, int argc, char** argv) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::string program = ((ec ? std::filesystem::path(".") : self.parent_path()) / name).string();
    std::vector<char*> args(argv, argv + argc);
    args.push_back(nullptr);
    ::execv(program.c_str(), args.data());
    return fmt::format("cannot start {}: {}", program, std::error_code(errno, std::generic_category()).message());
}

}  // namespace glint::app
