// SmallBlockPool (see small_block_pool.h for the contract).
#include "script/small_block_pool.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
// Under AddressSanitizer a block on a free list (or not carved yet) is poisoned, so a use after free of a Lua
// object is caught here as it would be with malloc.
#define POOL_POISON(p, n) ASAN_POISON_MEMORY_REGION(p, n)
#define POOL_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION(p, n)
#else
#define POOL_POISON(p, n) ((void)(p), (void)(n))
#define POOL_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

namespace meshedit {

SmallBlockPool::~SmallBlockPool() {
  for (void* slab : slabs_) {
    POOL_UNPOISON(slab, kSlabBytes);
    std::free(slab);
  }
}

void* SmallBlockPool::take(size_t bytes) {
  const size_t c = size_class(bytes);
  const size_t rounded = (c + 1) * kGranule;
  if (FreeBlock* block = free_[c]) {
    POOL_UNPOISON(block, rounded);
    free_[c] = block->next;
    return block;
  }
  if (size_t(end_ - next_) < rounded) {
    if (slabs_.size() == slabs_.capacity()) {
      try {
        slabs_.reserve(std::max<size_t>(16, 2 * slabs_.size()));
      } catch (const std::bad_alloc&) {
        return nullptr;
      }
    }
    void* slab = std::malloc(kSlabBytes);  // malloc's alignment is at least kGranule
    if (!slab) return nullptr;
    slabs_.push_back(slab);
    POOL_POISON(slab, kSlabBytes);
    next_ = static_cast<char*>(slab);
    end_ = next_ + kSlabBytes;
  }
  void* block = next_;
  next_ += rounded;
  POOL_UNPOISON(block, rounded);
  return block;
}

void SmallBlockPool::release(void* ptr, size_t bytes) {
  if (!ptr) return;
  if (!small(bytes)) {
    std::free(ptr);
    return;
  }
  auto* block = static_cast<FreeBlock*>(ptr);
  const size_t c = size_class(bytes);
  block->next = free_[c];
  free_[c] = block;
  POOL_POISON(block, (c + 1) * kGranule);
}

void* SmallBlockPool::resize(void* ptr, size_t old_bytes, size_t bytes) {
  if (!ptr) return small(bytes) ? take(bytes) : std::malloc(bytes);
  if (small(old_bytes) && small(bytes) && size_class(old_bytes) == size_class(bytes)) return ptr;
  if (!small(old_bytes) && !small(bytes)) return std::realloc(ptr, bytes);
  void* moved = small(bytes) ? take(bytes) : std::malloc(bytes);
  if (!moved) return nullptr;
  std::memcpy(moved, ptr, std::min(old_bytes, bytes));
  release(ptr, old_bytes);
  return moved;
}

}  // namespace meshedit
