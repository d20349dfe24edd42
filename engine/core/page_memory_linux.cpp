// page_memory on Linux: huge-page-aligned anonymous mappings that grow by moving their pages (see page_memory.h).
// The only file of engine/core that includes a system header; CMake links it when MESHEDIT_PAGE_MEMORY=linux.
#include "core/page_memory.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#include <sys/mman.h>

namespace meshedit::page_memory {
namespace {

// Maps `bytes` (rounded up to whole small pages) at a huge-page boundary: maps one huge page more than needed and
// unmaps the unaligned head and tail.
void* map_aligned(size_t bytes) {
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

}  // namespace

bool starts_on_huge_pages() { return true; }

void* allocate(size_t bytes) { return map_aligned(bytes); }

void release(void* p, size_t bytes) noexcept {
  if (p) munmap(p, mapped_size(bytes));
}

void* grow(void* p, size_t bytes, size_t used, size_t new_bytes) {
  void* grown = map_aligned(new_bytes);
  // MREMAP_FIXED replaces the fresh mapping at `grown` with p's pages plus fresh pages after them; p's own range is
  // unmapped. On failure nothing moved and the copy below runs instead.
  void* moved = mremap(p, mapped_size(bytes), mapped_size(new_bytes), MREMAP_MAYMOVE | MREMAP_FIXED, grown);
  if (moved != MAP_FAILED) return moved;
  if (used) std::memcpy(grown, p, used);
  release(p, bytes);
  return grown;
}

}  // namespace meshedit::page_memory
