// An allocator for large arrays (the BVH builder's primitives and nodes, the CPU walk's
// tree) that asks Linux for transparent huge pages. With 4 KiB pages, first touching a
// 100 MB array takes ~25k page faults, a large part of a big build's time
// (docs/design-notes.md, "Huge pages for the BVH build"), and a walk over a tree that
// size misses the TLB at most of its nodes.
// Debian's default THP mode is "madvise", so the pages must be asked for; Embree does
// the same. Small allocations, and systems without madvise, get plain operator new.
#pragma once

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vkpt::internal {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr size_t kHugePage = size_t(2) << 20;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes >= kHugePage) {
      // Whole, aligned huge pages; madvise is advice, so its failure is harmless.
      const size_t rounded = (bytes + kHugePage - 1) & ~(kHugePage - 1);
      void* p = ::operator new(rounded, std::align_val_t(kHugePage));
      madvise(p, rounded, MADV_HUGEPAGE);
      return static_cast<T*>(p);
    }
#endif
    return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
  }
  void deallocate(T* p, size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (n * sizeof(T) >= kHugePage) return ::operator delete(p, std::align_val_t(kHugePage));
#endif
    ::operator delete(p, std::align_val_t(alignof(T)));
  }
  // resize() default-initialises: trivial elements are left unwritten, for arrays
  // that are filled right after (a zero fill would touch every page twice).
  template <class U>
  void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U)) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const { return true; }
};

// A vector whose large buffers sit on huge pages; resize(n) leaves trivial elements
// uninitialised.
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace vkpt::internal
