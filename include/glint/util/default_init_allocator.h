#pragma once
/// \file A std::allocator whose containers default-initialise their elements: a
/// std::vector<T, DefaultInitAllocator<T>> of a trivial T leaves resize()'s new elements
/// unwritten instead of zeroing them, for arrays that are filled right after, in parallel.
/// The zeroing would be a single-threaded pass over memory that the fill overwrites, and
/// it would take every page fault of a fresh array on one thread.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace glint {

template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <typename U>
    explicit(false) DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

    /// Default-initialisation: nothing written for a trivial type.
    template <typename U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace glint
