#pragma once
/// \file Arrays that every ray reads (a mesh's triangle blocks): from 2 MiB on they are
/// placed on 2 MiB boundaries and offered to the kernel as transparent huge pages (Linux
/// `madvise(MADV_HUGEPAGE)`, as Embree's `hugepages` option does), so that the traversal's
/// scattered reads miss the TLB less. The 871,414-triangle dragon's 38.5 MB of blocks
/// traced camera rays 2-26 % faster in huge pages (docs/performance.md, "The build's page
/// faults").
///
/// Only those. A fresh huge page costs more than the 512 small pages it replaces wherever
/// the kernel must first find and clear a free 2 MiB block: on a virtual machine whose host
/// takes back the guest's free memory, 1-2 ms per MiB against 0.36 ms in 4 KiB faults
/// (docs/performance.md, "Fresh memory on an idle machine"). Everything else is an ordinary
/// vector: files' bytes, the builder's temporaries and images, written once and read a few
/// times, and the film, which every sample writes but whose 6 MB at 640×480 rendered two
/// spheres 11 ms slower after idling in huge pages and 2 ms faster back to back.
///
/// Smaller arrays, and systems without transparent huge pages, get ordinary memory.

#include "glint/util/uninitialized_allocator.h"

#include <cstddef>
#include <vector>

namespace glint {

namespace detail {
/// `bytes` aligned to `alignment`; from kHugePageBytes on, whole huge pages advised as such.
[[nodiscard]] void* allocate_huge_page_array(std::size_t bytes, std::size_t alignment);
/// Frees what allocate_huge_page_array(bytes, alignment) returned.
void free_huge_page_array(void* p, std::size_t bytes, std::size_t alignment) noexcept;
}  // namespace detail

/// The size of a transparent huge page on x86-64 and of the arrays that get them.
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

/// A standard allocator over detail::allocate_huge_page_array; stateless, so any two are
/// equal.
template <typename T>
struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <typename U>
    explicit(false) HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
    [[nodiscard]] T* allocate(std::size_t n) {
        return static_cast<T*>(detail::allocate_huge_page_array(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { detail::free_huge_page_array(p, n * sizeof(T), alignof(T)); }
    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;
    }
};

/// A std::vector over HugePageAllocator whose new elements are left unwritten
/// (uninitialized_allocator.h), so that a parallel fill takes the first touch of its pages
/// on every thread.
template <typename T>
using HugePageArray = std::vector<T, UninitializedAllocator<T, HugePageAllocator<T>>>;

}  // namespace glint
