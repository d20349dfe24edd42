// BigArrayAllocator: the allocator of HalfedgeMesh's arrays. Small arrays come from the heap as usual; an array of
// 4 MiB or more gets its own 2 MiB-aligned anonymous mapping marked MADV_HUGEPAGE.
//
// Why: a subdivided mesh of millions of faces is hundreds of megabytes written once. On the machines MeshEdit runs
// on, faulting in fresh 4 KiB pages costs about as much as the subdivision itself (~2 us a page, measured in
// ../shared/research/perf_anchors.md); transparent huge pages fault 512 times fewer pages. Where THP is off or
// refused, the mapping is ordinary memory and nothing else changes. MESHEDIT_NO_HUGEPAGES=1 in the environment
// skips the madvise, to measure what huge pages buy (peer_bench, 100k x 3 Loop: about 1.7x cold here).
//
// Invariants: construct() value-initialises like std::allocator unless MeshStorage::grow or resize_for_overwrite
// (halfedge_mesh.h) asked otherwise for its own thread; allocate(n) and deallocate(p, n) take the same branch for
// the same n (the size alone decides), so a block is always returned to the allocator that made it; the allocator
// is stateless, so any two compare equal and containers may swap or move storage freely. An mmap failure throws
// std::bad_alloc like operator new.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

#include <sys/mman.h>

namespace meshedit {

namespace big_array_detail {

inline constexpr size_t kHugePage = size_t(2) << 20;
inline constexpr size_t kThreshold = size_t(4) << 20;

// Set (on one thread, for the duration of a resize) by MeshStorage::grow and resize_for_overwrite, whose callers
// write every field of the new elements themselves: default construction of trivially copyable elements is then
// skipped, saving a pass over hundreds of megabytes.
inline thread_local bool skip_default_init = false;

// Sets skip_default_init for its lifetime, on this thread (also when a resize throws).
struct SkipDefaultInit {
  SkipDefaultInit() { skip_default_init = true; }
  ~SkipDefaultInit() { skip_default_init = false; }
  SkipDefaultInit(const SkipDefaultInit&) = delete;
  SkipDefaultInit& operator=(const SkipDefaultInit&) = delete;
};

inline constexpr size_t kSmallPage = size_t(4) << 10;

// The mapping ends at the last small page the array needs, not at a huge-page boundary: the kernel backs only
// whole aligned huge pages inside a mapping with huge pages, so the array's tail gets small pages and no memory is
// resident past what the array holds (up to 2 MiB per array otherwise, ~2 B per face of a subdivided mesh).
inline size_t mapped_size(size_t bytes) { return (bytes + kSmallPage - 1) & ~(kSmallPage - 1); }

// Maps `bytes` (rounded up to whole small pages) at a huge-page boundary: maps one huge page more than needed and
// unmaps the unaligned head and tail.
inline void* map_aligned(size_t bytes) {
  const size_t size = mapped_size(bytes);
  void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t aligned = (start + kHugePage - 1) & ~(uintptr_t(kHugePage) - 1);
  if (aligned > start) munmap(raw, aligned - start);
  const uintptr_t end = start + size + kHugePage;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
  void* p = reinterpret_cast<void*>(aligned);
#ifdef MADV_HUGEPAGE
  static const bool no_huge = std::getenv("MESHEDIT_NO_HUGEPAGES") != nullptr;
  if (!no_huge) madvise(p, size, MADV_HUGEPAGE);
#endif
  return p;
}

}  // namespace big_array_detail

template <class T>
struct BigArrayAllocator {
  using value_type = T;

  BigArrayAllocator() = default;
  template <class U>
  constexpr BigArrayAllocator(const BigArrayAllocator<U>&) noexcept {}

  T* allocate(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes < big_array_detail::kThreshold) return static_cast<T*>(::operator new(bytes));
    return static_cast<T*>(big_array_detail::map_aligned(bytes));
  }

  void deallocate(T* p, size_t n) noexcept {
    const size_t bytes = n * sizeof(T);
    if (bytes < big_array_detail::kThreshold) {
      ::operator delete(p);
      return;
    }
    munmap(p, big_array_detail::mapped_size(bytes));
  }

  // Value-initialises as std::allocator does, except while skip_default_init is set (see above).
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    if constexpr (std::is_trivially_copyable_v<U>) {
      if (big_array_detail::skip_default_init) return;
    }
    ::new (static_cast<void*>(p)) U();
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  friend constexpr bool operator==(const BigArrayAllocator&, const BigArrayAllocator<U>&) noexcept {
    return true;
  }
};

}  // namespace meshedit
