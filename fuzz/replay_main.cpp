/// \file A main() for fuzz targets built without libFuzzer (g++ builds, the default test
/// suite): runs LLVMFuzzerTestOneInput once on each file named, or on each file inside each
/// folder named, so the corpus and every past finding are replayed in every build.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

void replay(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t count = 0;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path arg = argv[i];
        std::vector<std::filesystem::path> files;
        if (std::filesystem::is_directory(arg)) {
            for (const auto& entry : std::filesystem::directory_iterator(arg))
                if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
            std::sort(files.begin(), files.end());  // a failure names the same file every run
        } else if (std::filesystem::is_regular_file(arg)) {
            files.push_back(arg);
        } else if (!std::filesystem::exists(arg)) {
            std::printf("%s: no such folder: no findings of this target to replay\n", argv[i]);
        } else {
            std::fprintf(stderr, "%s: not a file or folder\n", argv[i]);
            return 2;
        }
        for (const auto& file : files) {
            std::fprintf(stderr, "replaying %s\n", file.c_str());
            replay(file);
            ++count;
        }
    }
    if (count == 0) {  // a replay of nothing would pass whatever the target did
        std::fprintf(stderr, "nothing to replay: expected a corpus or regression inputs\n");
        return 1;
    }
    std::printf("%zu inputs replayed without a crash\n", count);
    return 0;
}
