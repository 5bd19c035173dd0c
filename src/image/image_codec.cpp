#include "image_codec.h"

#include "glint/image/image_io.h"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <string>

namespace glint::codec {

namespace {

/// Where the module may be: where the build put it (GLINT_OIIO_MODULE, for every program of
/// the build tree and its tests), else beside the running program (a copied or installed
/// glint with the module next to it).
std::vector<std::filesystem::path> module_candidates() {
    std::vector<std::filesystem::path> candidates{GLINT_OIIO_MODULE};
    std::array<char, 4096> exe{};
    if (const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1); n > 0)
        candidates.push_back(std::filesystem::path(std::string(exe.data(), std::size_t(n))).parent_path() /
                             std::filesystem::path(GLINT_OIIO_MODULE).filename());
    return candidates;
}

const Functions* load() {
    std::string reasons;
    for (const std::filesystem::path& path : module_candidates()) {
        // Never closed: OpenImageIO keeps threads and caches until the process ends.
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = ::dlerror();
            reasons += "; " + std::string(why ? why : path.string());
            continue;
        }
        if (auto entry = reinterpret_cast<EntryPoint>(::dlsym(handle, kEntryPoint))) return entry();
        reasons += "; " + path.string() + ": no " + kEntryPoint;
    }
    throw ImageError("cannot load Glint's OpenImageIO module (" + reasons.substr(2) + ")");
}

}  // namespace

const Functions& oiio() {
    // Loaded once, by the first thread that needs it (a function-local static's
    // initialisation is thread-safe); a failed load throws and is tried again next time.
    static const Functions* const functions = load();
    return *functions;
}

}  // namespace glint::codec
