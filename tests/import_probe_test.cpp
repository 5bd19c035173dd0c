// The guard around assimp (src/assets/import_probe.h): a child that crashes or ends badly
// becomes a SceneError naming the file and the cause; one that returns lets the caller go on.
#include "assets/import_probe.h"

#include "glint/diagnostics.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <csignal>
#include <cstdio>
#include <string>

namespace {

std::string probe_error(const std::function<void(Assimp::Importer&)>& import) {
    try {
        glint::probe_import(import, "model.ply");
    } catch (const glint::SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ImportProbe, AChildThatReturnsIsNotAnError) {
    EXPECT_EQ(probe_error([](Assimp::Importer&) {}), "");
}

TEST(ImportProbe, ACrashBecomesAnErrorNamingTheFileAndTheSignal) {
    const std::string error = probe_error([](Assimp::Importer&) {
        std::fputs("Assertion failed: nan in position\nsecond line\n", stderr);
        std::raise(SIGSEGV);
    });
    EXPECT_NE(
        error.find("model.ply: assimp crashed on this file (Segmentation fault): Assertion failed: nan in position;"),
        std::string::npos)
        << error;
    EXPECT_EQ(error.find("second line"), std::string::npos) << error;
}

TEST(ImportProbe, AnAbnormalExitStatusIsAnError) {
    // What a sanitizer does after its report in the child.
    const std::string error = probe_error([](Assimp::Importer&) { ::_exit(1); });
    EXPECT_NE(error.find("model.ply: assimp crashed on this file (exit status 1)"), std::string::npos) << error;
}

TEST(ImportProbe, MuchOutputNeitherBlocksTheChildNorFloodsTheMessage) {
    // Far more than a pipe holds (64 KiB): the parent must drain it while the child writes.
    const std::string error = probe_error([](Assimp::Importer&) {
        const std::string line(1000, 'x');
        for (int i = 0; i < 1000; ++i) std::printf("%s\n", line.c_str());
        std::fflush(stdout);
        std::abort();
    });
    EXPECT_NE(error.find("(Aborted): xxx"), std::string::npos) << error.substr(0, 200);
    EXPECT_LT(error.size(), 1300u);
}
