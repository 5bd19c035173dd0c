#pragma once
// Files a test writes and reads in a folder of its own.

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

namespace glint_test {

/// A fresh empty directory under the system temp dir, unique per test.
inline std::filesystem::path temp_dir() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    // The process id keeps two runs of the suite at once (two checkouts, a CI job and a
    // developer) out of each other's files.
    const auto dir = std::filesystem::temp_directory_path() /
                     ("glint_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace glint_test
