#pragma once
/// \file Arrays of megabytes that a render fills once (a mesh's vertices and indices, the
/// BVH builder's temporaries, the wide tree's leaf ranges, the triangle blocks, the film):
/// from 2 MiB on they are placed on 2 MiB boundaries and offered to the kernel as
/// transparent huge pages (Linux `madvise(MADV_HUGEPAGE)`, as Embree does with its
/// `hugepages` option), so that the first write to each 2 MiB costs one page fault instead
/// of 512. On a virtual machine a 4 KiB fault costs about 10 µs: building the BVH of the
/// 202,520-triangle dragon took 11,500 of them, two thirds of the build (docs/performance.md,
/// "Page faults" and "The build's page faults").
///
/// Smaller arrays, and systems without transparent huge pages, get ordinary memory.

#include <cstddef>
#include <vector>

namespace glint {

namespace detail {
/// `bytes` aligned to `alignment`; from kHugePageBytes on, whole huge pages advised as such.
[[nodiscard]] void* allocate_large_array(std::size_t bytes, std::size_t alignment);
/// Frees what allocate_large_array(bytes, alignment) returned.
void free_large_array(void* p, std::size_t bytes, std::size_t alignment) noexcept;
}  // namespace detail

/// The size of a transparent huge page on x86-64 and of the arrays that get them.
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

/// A standard allocator over detail::allocate_large_array; stateless, so any two are equal.
template <typename T>
struct LargeArrayAllocator {
    using value_type = T;
    LargeArrayAllocator() = default;
    template <typename U>
    explicit(false) LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
    [[nodiscard]] T* allocate(std::size_t n) {
        return static_cast<T*>(detail::allocate_large_array(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { detail::free_large_array(p, n * sizeof(T), alignof(T)); }
    template <typename U>
    bool operator==(const LargeArrayAllocator<U>&) const noexcept {
        return true;
    }
};

/// A std::vector whose storage comes from LargeArrayAllocator.
template <typename T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace glint
