// big_blocks: the raw memory behind MeshArray (mesh_array.h). A block under 4 MiB comes from the heap as usual; a
// block of 4 MiB or more comes from the page_memory seam (page_memory.h). On Linux that makes it its own 2 MiB-aligned
// anonymous mapping marked MADV_HUGEPAGE, which grows by moving its pages to a bigger mapping (mremap), not by
// copying its bytes; elsewhere (page_memory_portable.cpp) it comes from the C heap and grows with realloc.
//
// Why: a subdivided mesh of millions of faces is hundreds of megabytes written once. On the machines MeshEdit runs
// on, faulting in fresh 4 KiB pages costs about as much as the subdivision itself; transparent huge
// pages fault 512 times fewer pages. Where THP is off or refused, the mapping is ordinary memory and nothing else
// changes. MESHEDIT_NO_HUGEPAGES=1 in the environment skips the madvise, to measure what huge pages buy (peer_bench
// --cold). Growing in place matters for the first edit that appends to
// an exactly sized array (the first split after opening a mesh or after Loop subdivision): at 1M faces that array
// holds 60 MB of halfedges, which a copy into fresh memory would have to fault in and write.
//
// Invariants: the size of a block alone decides where it came from (is_mapped), so allocate, release and regrow
// agree on it. Out of memory: the rule of docs/ARCHITECTURE.md (Memory running out); release never throws. The
// small-block path stays inline here; only big blocks cross the seam.
#pragma once

#include <cstddef>
#include <cstring>
#include <new>

#include "core/page_memory.h"

namespace meshedit::big_blocks {

inline constexpr size_t kThreshold = size_t(4) << 20;

inline bool is_mapped(size_t bytes) { return bytes >= kThreshold; }

// A block of `bytes` (> 0), its contents unset.
inline void* allocate(size_t bytes) { return is_mapped(bytes) ? page_memory::allocate(bytes) : ::operator new(bytes); }

// Gives back a block of `bytes` from allocate or regrow (nullptr: nothing).
inline void release(void* p, size_t bytes) noexcept {
  if (!p) return;
  if (is_mapped(bytes)) {
    page_memory::release(p, bytes);
  } else {
    ::operator delete(p);
  }
}

// A block of `new_bytes` (>= bytes) whose first `used` bytes are those of `p` (a block of `bytes`, or nullptr), the
// rest unset; `p` is released once the new block is there. A big block grows through the seam (on Linux its pages
// are moved, aligned, to the new mapping, which costs page-table updates, not a copy).
inline void* regrow(void* p, size_t bytes, size_t used, size_t new_bytes) {
  if (p && is_mapped(bytes)) return page_memory::grow(p, bytes, used, new_bytes);
  void* grown = allocate(new_bytes);
  if (used) std::memcpy(grown, p, used);
  release(p, bytes);
  return grown;
}

}  // namespace meshedit::big_blocks
