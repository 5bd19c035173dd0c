#pragma once
/// \file An allocator adaptor whose vectors leave new elements unwritten: resize() makes no
/// pass over the memory, so an array that is filled right after, in parallel, takes its
/// page faults on every thread instead of one, and costs no zeroing that the fill
/// overwrites (the binary BVH's nodes, the wide nodes, the triangle blocks).
///
/// Only for trivially copyable, trivially destructible types (implicit-lifetime types,
/// C++20 [intro.object]: their allocation itself begins their lifetime); every element must
/// be written before it is read.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint {

template <typename T, typename Base = std::allocator<T>>
struct UninitializedAllocator : Base {
    template <typename U>
    struct rebind {
        using other = UninitializedAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
    };
    UninitializedAllocator() = default;
    template <typename U, typename OtherBase>
    explicit(false) UninitializedAllocator(const UninitializedAllocator<U, OtherBase>& other) noexcept
        : Base(static_cast<const OtherBase&>(other)) {}

    /// No value: nothing written.
    template <typename U>
    void construct(U*) noexcept {
        static_assert(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>,
                      "only an implicit-lifetime type may be left unwritten");
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

/// A std::vector whose new elements are left unwritten (see above).
template <typename T>
using UninitializedArray = std::vector<T, UninitializedAllocator<T>>;

}  // namespace glint
