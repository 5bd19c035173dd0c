#include "image_codec.h"

#include "glint/image/image_io.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>

namespace glint::codec {

namespace {

/// Where the module may be: where the build put it (GLINT_OIIO_MODULE, for every program of
/// the build tree and its tests); else where `cmake --install` puts it, found from the
/// running program (bin/glint: lib/glint/ under the same prefix; a copied glint: beside it)
/// or from the shared object this code is linked into (the Python module: beside it).
std::vector<std::filesystem::path> module_candidates() {
    const std::filesystem::path name = std::filesystem::path(GLINT_OIIO_MODULE).filename();
    std::vector<std::filesystem::path> candidates{GLINT_OIIO_MODULE};
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
    // Each once: in the build tree several name the same file.
    std::vector<std::filesystem::path> unique;
    for (const std::filesystem::path& c : candidates)
        if (std::find(unique.begin(), unique.end(), c) == unique.end()) unique.push_back(c);
    return unique;
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

// Sanitizer builds: loading the module gives its libraries dynamic TLS blocks, and the
// sanitizer runtimes of GCC up to 13 and LLVM up to 16 misread some of them in their
// __tls_get_addr interceptor (a block that lands 16 bytes past a page boundary is taken for a
// glibc 2.19 header), so LeakSanitizer's tracer crashes at exit: google/sanitizers#1322,
// #1342. Seen every time after a multithreaded render that read a texture. Turning the
// interceptor off is the workaround those reports give; programs linking this file get it
// as their default (ASAN_OPTIONS still adds to it).
#if defined(__SANITIZE_ADDRESS__)
#define GLINT_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GLINT_ADDRESS_SANITIZER 1
#endif
#endif
#ifdef GLINT_ADDRESS_SANITIZER
extern "C" const char* __asan_default_options() { return "intercept_tls_get_addr=0"; }
#endif
