// assimp's sandbox (src/assets/isolated_import.h): the child's result comes back whole, what
// it throws comes back as a SceneError with the same words, and a child that crashes or ends
// badly becomes a SceneError naming the file and the cause.
#include "assets/isolated_import.h"

#include "glint/diagnostics.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

std::string isolated_error(const std::function<std::string()>& work) {
    try {
        (void)glint::run_isolated(work, "model.ply: cannot read mesh file");
    } catch (const glint::SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(IsolatedImport, TheChildsBytesComeBackWhole) {
    // Far more than a pipe holds, with every byte value, and bytes after a zero.
    std::string big(3 << 20, '\0');
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = char((i * 2654435761u) >> 24);
    const auto back = glint::run_isolated([&] { return big; }, "x");
    EXPECT_EQ(std::string(back.begin(), back.end()), big);
    EXPECT_TRUE(glint::run_isolated([] { return std::string(); }, "x").empty());
}

TEST(IsolatedImport, TheChildRunsInItsOwnMemory) {
    int touched = 0;
    (void)glint::run_isolated(
        [&] {
            touched = 1;
            return std::string("done");
        },
        "x");
    EXPECT_EQ(touched, 0);
}

TEST(IsolatedImport, ASceneErrorComesBackWithItsOwnWords) {
    EXPECT_EQ(
        isolated_error([]() -> std::string { throw glint::SceneError("model.ply: mesh 0: face 3 uses vertex 9"); }),
        "model.ply: mesh 0: face 3 uses vertex 9");
}

TEST(IsolatedImport, AnyOtherExceptionComesBackWithTheContext) {
    EXPECT_EQ(isolated_error([]() -> std::string { throw std::runtime_error("out of patience"); }),
              "model.ply: cannot read mesh file: out of patience");
}

TEST(IsolatedImport, ACrashBecomesAnErrorNamingTheFileAndTheSignal) {
    const std::string error = isolated_error([]() -> std::string {
        std::fputs("Assertion failed: nan in position\nsecond line\n", stderr);
        std::raise(SIGSEGV);
        return "unreachable";
    });
    EXPECT_NE(error.find("model.ply: cannot read mesh file: assimp crashed on this file (Segmentation fault): "
                         "Assertion failed: nan in position;"),
              std::string::npos)
        << error;
    EXPECT_EQ(error.find("second line"), std::string::npos) << error;
}

TEST(IsolatedImport, AnAbnormalExitStatusIsAnError) {
    // What a sanitizer does after its report in the child.
    const std::string error = isolated_error([]() -> std::string { ::_exit(1); });
    EXPECT_NE(error.find("model.ply: cannot read mesh file: assimp crashed on this file (exit status 1)"),
              std::string::npos)
        << error;
}

TEST(IsolatedImport, MuchOutputNeitherBlocksTheChildNorFloodsTheMessage) {
    // Far more than a pipe holds (64 KiB): the parent must drain it while the child writes.
    const std::string error = isolated_error([]() -> std::string {
        const std::string line(1000, 'x');
        for (int i = 0; i < 1000; ++i) std::printf("%s\n", line.c_str());
        std::fflush(stdout);
        std::abort();
    });
    EXPECT_NE(error.find("(Aborted): xxx"), std::string::npos) << error.substr(0, 200);
    EXPECT_LT(error.size(), 1300u);
}
