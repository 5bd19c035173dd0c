#pragma once
// The glint command line run from a test: its exit status and what it printed.

#include "test_files.h"

#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace glint_test {

struct CliResult {
    int exit_code = -1;
    std::string err;
    std::string out;
};

/// Run `cli` with `args` (a shell word list); its output is kept in `dir`.
inline CliResult run_cli(const std::string& cli, const std::string& args, const std::filesystem::path& dir) {
    const std::filesystem::path err = dir / "stderr.txt", out = dir / "stdout.txt";
    const std::string cmd = cli + " " + args + " > " + out.string() + " 2> " + err.string();
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(err), read_file(out)};
}

}  // namespace glint_test
