// BvhNodeAllocator: where Bvh::nodes (stages/05_bvh.h) keeps its nodes, so that sibling
// pairs share a cache line. Not part of the assignment: a builder uses Bvh::nodes like any
// std::vector.
#pragma once

#include <cstddef>
#include <limits>
#include <new>

namespace raylab {

// The allocator of Bvh::nodes (nothing to do with the assignment: use Bvh::nodes like any
// std::vector). It places nodes[0] in the second half of a 64-byte cache line. A builder that
// appends the root first and then both children of a node at once (as the contract says) puts
// every sibling pair at an odd index, so each pair then fills exactly one cache line, and a
// traversal that reads both children of a node loads one line, not two.
template <typename T>
struct BvhNodeAllocator {
  using value_type = T;
  static constexpr std::size_t kCacheLine = 64;
  static constexpr std::size_t kRootOffset = 32;  // nodes[1] starts a cache line

  BvhNodeAllocator() noexcept = default;
  template <typename U>
  BvhNodeAllocator(const BvhNodeAllocator<U>&) noexcept {}

  T* allocate(std::size_t count) {
    if (count > (std::numeric_limits<std::size_t>::max() - kCacheLine) / sizeof(T))
      throw std::bad_array_new_length();
    auto* line = static_cast<unsigned char*>(
        ::operator new(count * sizeof(T) + kCacheLine, std::align_val_t{kCacheLine}));
    return reinterpret_cast<T*>(line + kRootOffset);
  }
  void deallocate(T* nodes, std::size_t) noexcept {
    ::operator delete(reinterpret_cast<unsigned char*>(nodes) - kRootOffset, std::align_val_t{kCacheLine});
  }
  template <typename U>
  bool operator==(const BvhNodeAllocator<U>&) const noexcept { return true; }
  template <typename U>
  bool operator!=(const BvhNodeAllocator<U>&) const noexcept { return false; }
};

}  // namespace raylab
