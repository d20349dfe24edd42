// page_memory anywhere (see page_memory.h): big blocks come from the C heap and grow with std::realloc, which may
// extend a block in place or move it. CMake links this file when MESHEDIT_PAGE_MEMORY=portable (the default off
// Linux); scripts/clang_build.sh builds and tests it on Linux so it cannot rot.
#include "core/page_memory.h"

#include <cstdlib>
#include <new>

namespace meshedit::page_memory {

bool starts_on_huge_pages() { return false; }

void* allocate(size_t bytes) {
  void* p = std::malloc(bytes);
  if (!p) throw std::bad_alloc();
  return p;
}

void release(void* p, size_t /*bytes*/) noexcept { std::free(p); }

// realloc copies all `bytes` where it moves the block, not just the `used` ones: the same result, at most a little
// more copying. On failure it returns null and leaves `p` as it was.
void* grow(void* p, size_t /*bytes*/, size_t /*used*/, size_t new_bytes) {
  void* grown = std::realloc(p, new_bytes);
  if (!grown) throw std::bad_alloc();
  return grown;
}

}  // namespace meshedit::page_memory
