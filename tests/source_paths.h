#pragma once
// Where tests find the repository's files and the shared assets (tests/CMakeLists.txt sets
// GLINT_SOURCE_DIR and GLINT_SHARED_DATA_DIR). Defined once for all test files: the test
// binaries are unity builds, in which two files' constants of one name would collide.

#include <filesystem>

namespace glint_test {

inline const std::filesystem::path kSourceDir{GLINT_SOURCE_DIR};
inline const std::filesystem::path kScenesDir = kSourceDir / "scenes";
inline const std::filesystem::path kTestDataDir = kSourceDir / "tests" / "data";
inline const std::filesystem::path kSharedDataDir{GLINT_SHARED_DATA_DIR};
inline const std::filesystem::path kSharedMeshDir = kSharedDataDir / "meshes";

}  // namespace glint_test
