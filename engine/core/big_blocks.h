// big_blocks: the raw memory behind MeshArray (mesh_array.h). A block under 4 MiB comes from the heap as usual; a
// block of 4 MiB or more is its own 2 MiB-aligned anonymous mapping marked MADV_HUGEPAGE, and grows by moving its
// pages to a bigger mapping (mremap), not by copying its bytes.
//
// Why: a subdivided mesh of millions of faces is hundreds of megabytes written once. On the machines MeshEdit runs
// on, faulting in fresh 4 KiB pages costs about as much as the subdivision itself (~2 us a page); transparent huge
// pages fault 512 times fewer pages. Where THP is off or refused, the mapping is ordinary memory and nothing else
// changes. MESHEDIT_NO_HUGEPAGES=1 in the environment skips the madvise, to measure what huge pages buy (peer_bench
// --cold, 100k faces x 3 levels of Loop: about 1.7x). Growing in place matters for the first edit that appends to
// an exactly sized array (the first split after opening a mesh or after Loop subdivision): at 1M faces that array
// holds 60 MB of halfedges, which a copy into fresh memory would have to fault in and write.
//
// Invariants: the size of a block alone decides where it came from (is_mapped), so allocate, release and regrow
// agree on it; a mapping ends at the last small page the block needs; every function either does all it says or
// throws std::bad_alloc with the block untouched (release never throws).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#include <sys/mman.h>

namespace meshedit::big_blocks {

inline constexpr size_t kHugePage = size_t(2) << 20;
inline constexpr size_t kThreshold = size_t(4) << 20;
inline constexpr size_t kSmallPage = size_t(4) << 10;

inline bool is_mapped(size_t bytes) { return bytes >= kThreshold; }

// The mapping ends at the last small page the block needs, not at a huge-page boundary: the kernel backs only
// whole aligned huge pages inside a mapping with huge pages, so the block's tail gets small pages and no memory is
// resident past what the block holds (up to 2 MiB per array otherwise, ~2 B per face of a subdivided mesh).
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

// A block of `bytes` (> 0), its contents unset.
inline void* allocate(size_t bytes) { return is_mapped(bytes) ? map_aligned(bytes) : ::operator new(bytes); }

// Gives back a block of `bytes` from allocate or regrow (nullptr: nothing).
inline void release(void* p, size_t bytes) noexcept {
  if (!p) return;
  if (is_mapped(bytes)) {
    munmap(p, mapped_size(bytes));
  } else {
    ::operator delete(p);
  }
}

// A block of `new_bytes` (>= bytes) whose first `used` bytes are those of `p` (a block of `bytes`, or nullptr), the
// rest unset; `p` is released. A mapped block keeps its pages: they are moved, aligned, to the new mapping, which
// costs page-table updates, not a copy. Out of memory, throws std::bad_alloc with `p` as it was.
inline void* regrow(void* p, size_t bytes, size_t used, size_t new_bytes) {
  void* grown = allocate(new_bytes);
  if (p && is_mapped(bytes) && is_mapped(new_bytes)) {
    // MREMAP_FIXED replaces the fresh mapping at `grown` with p's pages plus fresh pages after them; p's own range
    // is unmapped. On failure nothing moved and the copy below runs instead.
    void* moved = mremap(p, mapped_size(bytes), mapped_size(new_bytes), MREMAP_MAYMOVE | MREMAP_FIXED, grown);
    if (moved != MAP_FAILED) return moved;
  }
  if (used) std::memcpy(grown, p, used);
  release(p, bytes);
  return grown;
}

}  // namespace meshedit::big_blocks
