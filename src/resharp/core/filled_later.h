#pragma once
/// Arrays sized without a pass of zeros, for stages that write every entry right after.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace resharp {

/// An allocator whose construction without a value leaves a trivial element as it is: for
/// arrays that are sized and then written entry by entry (build_connectivity(), the
/// curvatures), so that sizing them costs no pass of zeros over the memory (megabytes on a large
/// mesh). Copies and values given are constructed as by std::allocator. Whoever sizes such an
/// array must write every entry before anything reads it.
template <class T>
struct FillLaterAllocator : std::allocator<T> {
    using std::allocator<T>::allocator;
    template <class U>
    struct rebind {
        using other = FillLaterAllocator<U>;
    };
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

/// A std::vector that resize() leaves unwritten (FillLaterAllocator).
template <class T>
using FilledLater = std::vector<T, FillLaterAllocator<T>>;

}  // namespace resharp
