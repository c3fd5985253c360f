#pragma once
// A std::vector whose resize() leaves new elements default-initialized (for int and double:
// not written) instead of value-initialized (zeroed). For the large arrays that a parallel
// loop fills completely right after: zeroing them first was a serial pass over fresh memory,
// and on this VM the first touch of a fresh page is most of what such a pass costs (the
// sparsity pattern's 634 MB scatter table at benchmark32), so the pages are better first
// touched by the threads that fill them.
#include <memory>
#include <type_traits>
#include <vector>

namespace magfem {

template <class T, class Base = std::allocator<T>> class DefaultInitAllocator : public Base {
public:
  using Traits = std::allocator_traits<Base>;
  template <class U> struct rebind {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };
  using Base::Base;
  // resize(n): default-initialize (the only difference from Base).
  template <class U> void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args> void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

template <class T> using DefaultInitVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace magfem
