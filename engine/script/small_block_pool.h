// SmallBlockPool: the free lists behind LuaRuntime's allocator for the small blocks a script makes by the
// hundred thousand (element handles, vec3 tables and their nodes, short strings, closures). Taking a block from a
// list and putting it back is a few instructions, where malloc and free cost a few hundred once the collector
// frees blocks in bursts.
//
// Invariants:
// - Blocks of 1 .. kMaxBytes bytes come from the pool, rounded up to a multiple of kGranule; every other size
//   goes to malloc. Which one owns a block is decided by its size alone, so the caller must give back the size it
//   asked for (Lua's allocator contract does) and resize() moves a block across the boundary when its size does.
// - Blocks are kGranule-aligned (as malloc's are), carved from slabs of kSlabBytes.
// - Slabs go back to the system only when the pool is destroyed: the pool holds at most the peak of small
//   blocks in use at once, plus one partly used slab. The bytes in use are counted by the caller (LuaRuntime's
//   memory cap), not here.
// - Not thread-safe: one pool per Lua state.
#pragma once

#include <cstddef>
#include <vector>

namespace meshedit {

class SmallBlockPool {
 public:
  static constexpr size_t kGranule = 16;
  static constexpr size_t kMaxBytes = 256;
  static constexpr size_t kSlabBytes = size_t(64) << 10;

  SmallBlockPool() = default;
  SmallBlockPool(const SmallBlockPool&) = delete;
  SmallBlockPool& operator=(const SmallBlockPool&) = delete;
  ~SmallBlockPool();

  // realloc with sizes: a new block when ptr is null, the same or a moved block otherwise (the contents up to
  // the smaller size kept); nullptr when memory is exhausted (the old block is then untouched). bytes > 0.
  void* resize(void* ptr, size_t old_bytes, size_t bytes);
  // free for a block of `bytes` bytes (ptr may be null).
  void release(void* ptr, size_t bytes);

 private:
  struct FreeBlock {
    FreeBlock* next;
  };
  static constexpr size_t kClasses = kMaxBytes / kGranule;

  static bool small(size_t bytes) { return bytes != 0 && bytes <= kMaxBytes; }
  static size_t size_class(size_t bytes) { return (bytes - 1) / kGranule; }
  void* take(size_t bytes);

  FreeBlock* free_[kClasses] = {};
  char* next_ = nullptr;  // the unused part of the newest slab
  char* end_ = nullptr;
  std::vector<void*> slabs_;
};

}  // namespace meshedit
