#include "glint/util/huge_page_array.h"

#include <algorithm>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace glint::detail {

namespace {

/// Arrays are rounded up to whole huge pages, so that the advice covers the last one.
std::size_t huge_page_bytes(std::size_t bytes) {
    return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

/// Where an array of `bytes` starts: large ones on a huge page, small ones as their type asks.
std::align_val_t array_alignment(std::size_t bytes, std::size_t alignment) {
    return std::align_val_t(bytes < kHugePageBytes ? alignment : std::max(alignment, kHugePageBytes));
}

}  // namespace

void* allocate_huge_page_array(std::size_t bytes, std::size_t alignment) {
    if (bytes < kHugePageBytes) return ::operator new(bytes, array_alignment(bytes, alignment));
    const std::size_t rounded = huge_page_bytes(bytes);
    void* p = ::operator new(rounded, array_alignment(bytes, alignment));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: where transparent huge pages are off, the kernel refuses it and the
    // array keeps small pages.
    (void)::madvise(p, rounded, MADV_HUGEPAGE);
#endif
    return p;
}

void free_huge_page_array(void* p, std::size_t bytes, std::size_t alignment) noexcept {
    ::operator delete(p, array_alignment(bytes, alignment));
}

}  // namespace glint::detail
