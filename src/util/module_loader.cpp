#include "glint/util/module_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <vector>

namespace glint {

namespace {

/// Where a module may be, each place once (in the build tree several name the same file).
std::vector<std::filesystem::path> module_candidates(const std::filesystem::path& built) {
    const std::filesystem::path name = built.filename();
    std::vector<std::filesystem::path> candidates{built};
    std::array<char, 4096> exe{};
    if (const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1); n > 0) {
        const auto folder = std::filesystem::path(std::string(exe.data(), std::size_t(n))).parent_path();
        candidates.push_back(folder.parent_path() / "lib" / "glint" / name);
        candidates.push_back(folder / name);
    }
    Dl_info self{};
    if (::dladdr(reinterpret_cast<const void*>(&module_candidates), &self) != 0 && self.dli_fname &&
        std::filesystem::path(self.dli_fname).is_absolute())
        candidates.push_back(std::filesystem::path(self.dli_fname).parent_path() / name);
    std::vector<std::filesystem::path> unique;
    for (const std::filesystem::path& c : candidates)
        if (std::find(unique.begin(), unique.end(), c) == unique.end()) unique.push_back(c);
    return unique;
}

}  // namespace

void* load_module_entry(const std::filesystem::path& built, const char* entry, std::string& reasons) {
    reasons.clear();
    for (const std::filesystem::path& path : module_candidates(built)) {
        // Never closed: OpenImageIO and OpenEXR keep threads and caches until the process ends.
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = ::dlerror();
            reasons += (reasons.empty() ? "" : "; ") + std::string(why ? why : path.string());
            continue;
        }
        if (void* function = ::dlsym(handle, entry)) return function;
        reasons += (reasons.empty() ? "" : "; ") + path.string() + ": no " + entry;
    }
    return nullptr;
}

}  // namespace glint
