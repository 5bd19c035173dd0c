#include "glint/util/large_array.h"

#include <algorithm>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace glint::detail {

namespace {

/// Large arrays are rounded up to whole huge pages, so that the advice covers the last one.
std::size_t huge_page_bytes(std::size_t bytes) {
    return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

}  // namespace

void* allocate_large_array(std::size_t bytes, std::size_t alignment) {
    if (bytes < kHugePageBytes) return ::operator new(bytes, std::align_val_t(alignment));
    const std::size_t rounded = huge_page_bytes(bytes);
    void* p = ::operator new(rounded, std::align_val_t(std::max(alignment, kHugePageBytes)));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: where transparent huge pages are off, the kernel refuses it and the
    // array keeps small pages.
    (void)::madvise(p, rounded, MADV_HUGEPAGE);
#endif
    return p;
}

void free_large_array(void* p, std::size_t bytes, std::size_t alignment) noexcept {
    if (bytes < kHugePageBytes) {
        ::operator delete(p, std::align_val_t(alignment));
        return;
    }
    ::operator delete(p, std::align_val_t(std::max(alignment, kHugePageBytes)));
}

}  // namespace glint::detail
