#include "image_codec.h"

#include "glint/image/image_io.h"
#include "glint/util/module_loader.h"

namespace glint::codec {

// Each loaded once, by the first thread that needs it (a function-local static's
// initialisation is thread-safe); a failed load throws and is tried again next time.
const Functions& oiio() {
    static const Functions& functions =
        load_module_table<Functions, ImageError>(GLINT_OIIO_MODULE, kOiioEntryPoint, "OpenImageIO");
    return functions;
}

const ExrFunctions& exr() {
    static const ExrFunctions& functions =
        load_module_table<ExrFunctions, ImageError>(GLINT_EXR_MODULE, kExrEntryPoint, "OpenEXR");
    return functions;
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
