#pragma once
/// \file
/// A std::vector whose `resize` leaves new elements of trivial types uninitialised, for large
/// arrays that parallel code fills right after sizing them (the wide BVH's nodes and triangle
/// blocks): a plain `resize` would first write every byte on one thread. Blocks of
/// kLargeBlockBytes (1 MiB) or more come in huge pages (large_block.h).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "raylab/core/large_block.h"

namespace raylab {

/// std::allocator, except that constructing an element without arguments default-initialises
/// it (for a trivial type: no write at all) instead of value-initialising it (zeroing), and that
/// blocks of kLargeBlockBytes or more come from allocate_large_block.
template <class T>
class DefaultInitAllocator : public std::allocator<T> {
 public:
  using value_type = T;

  DefaultInitAllocator() noexcept = default;
  /// Converts from the allocator of another element type (as containers rebind).
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>& /*other*/) noexcept {}

  /// The allocator for elements of type U.
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };

  /// Room for `n` elements: from allocate_large_block when that is kLargeBlockBytes or more.
  T* allocate(std::size_t n) {
    if (large(n)) return static_cast<T*>(allocate_large_block(n * sizeof(T)));
    return std::allocator<T>::allocate(n);
  }
  /// Frees what allocate(n) gave.
  void deallocate(T* p, std::size_t n) noexcept {
    if (large(n)) {
      free_large_block(p, n * sizeof(T));
    } else {
      std::allocator<T>::deallocate(p, n);
    }
  }

  /// Default-initialises an element (for a trivial type this writes nothing).
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  /// Constructs an element from `args`, as std::allocator does.
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

 private:
  // Whether `n` elements make a large block (not when n * sizeof(T) overflows: std::allocator
  // refuses those).
  static bool large(std::size_t n) { return n <= SIZE_MAX / sizeof(T) && is_large_block(n * sizeof(T)); }
};

/// Allocators of this family are interchangeable.
template <class T, class U>
bool operator==(const DefaultInitAllocator<T>& /*a*/, const DefaultInitAllocator<U>& /*b*/) noexcept {
  return true;
}

/// A vector whose `resize` does not write the new elements of a trivial type; everything else
/// is std::vector's.
template <class T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace raylab
