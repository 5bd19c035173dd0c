#include "glint/util/whole_file.h"
#include "glint/diagnostics.h"
#include "glint/integrators/checkpoint.h"
#include "glint/scene_format/toml_scene_loader.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace glint {
namespace {

namespace fs = std::filesystem;

class WholeFile : public testing::Test {
protected:
    void SetUp() override { dir_ = glint_test::temp_dir(); }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(WholeFile, ReadsEveryByteAndNothingOfWhatIsNoFile) {
    const std::string bytes("a\0b\r\n\xff end", 10);
    const fs::path file = dir_ / "bytes.bin";
    glint_test::write_file(file, bytes);
    EXPECT_EQ(read_whole_file(file), bytes);
    glint_test::write_file(dir_ / "empty.bin", "");
    EXPECT_EQ(read_whole_file(dir_ / "empty.bin"), std::string());
    EXPECT_FALSE(read_whole_file(dir_));
    EXPECT_FALSE(read_whole_file(dir_ / "absent.toml"));
}

TEST_F(WholeFile, AFolderOrAMissingFileIsNamedByTheSceneLoaderAndTheCheckpoint) {
    for (const fs::path& path : {dir_, dir_ / "absent.toml"}) {
        try {
            (void)load_toml_scene(path);
            ADD_FAILURE() << path << " loaded";
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), path.string() + ": no such scene file");
        }
        try {
            (void)scene_file_fingerprint(path);
            ADD_FAILURE() << path << " fingerprinted";
        } catch (const CheckpointError& e) {
            EXPECT_EQ(std::string(e.what()), path.string() + ": cannot be read");
        }
    }
}

}  // namespace
}  // namespace glint
