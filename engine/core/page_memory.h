// page_memory: the one seam between engine/core and the operating system's virtual memory. big_blocks.h takes every
// block of 4 MiB or more from here; nothing else in engine/core includes a system header or calls a system's
// memory functions, so porting the core (macOS, Windows, the web) means choosing an implementation, not editing code.
//
// One implementation is linked per build, chosen by CMake's MESHEDIT_PAGE_MEMORY (engine/core/CMakeLists.txt):
// - linux (page_memory_linux.cpp, the default on Linux): each block is its own anonymous mapping starting at a
//   2 MiB boundary and marked MADV_HUGEPAGE (skipped when MESHEDIT_NO_HUGEPAGES is set in the environment), ending
//   at the last 4 KiB page it needs (mapped_size); grow() moves the block's pages to a bigger mapping (mremap)
//   instead of copying its bytes. Why huge pages and moved pages pay off: big_blocks.h.
// - portable (page_memory_portable.cpp, the default everywhere else, Emscripten included): std::malloc,
//   std::realloc and std::free. scripts/clang_build.sh builds and tests it on Linux too.
//
// Invariants (both): a block holds at least the bytes asked for, aligned for any scalar type; grow() keeps the
// first `used` bytes; out of memory, allocate() and grow() keep the rule of docs/ARCHITECTURE.md (Memory running out),
// the old block still the caller's; release() never throws. A block goes back through the seam that gave it, with the
// byte count it was asked for (or last grown to).
#pragma once

#include <cstddef>

namespace meshedit::page_memory {

inline constexpr size_t kSmallPage = size_t(4) << 10;
inline constexpr size_t kHugePage = size_t(2) << 20;

// The linux seam's mapping ends at the last small page the block needs, not at a huge-page boundary: the kernel
// backs only whole aligned huge pages inside a mapping with huge pages, so the block's tail gets small pages and no
// memory is resident past what the block holds (up to 2 MiB per array otherwise, ~2 B per face of a subdivided mesh).
inline size_t mapped_size(size_t bytes) { return (bytes + kSmallPage - 1) & ~(kSmallPage - 1); }

// Whether this build's blocks start at a kHugePage boundary (the linux seam), for the tests that check it.
bool starts_on_huge_pages();

// A block of `bytes` (> 0), its contents unset.
void* allocate(size_t bytes);

// Gives back a block of `bytes` from allocate or grow (nullptr: nothing).
void release(void* p, size_t bytes) noexcept;

// A block of `new_bytes` (>= bytes) whose first `used` (<= bytes) bytes are those of `p` (a block of `bytes`, not
// null), the rest unset; `p` is released once the new block is there.
void* grow(void* p, size_t bytes, size_t used, size_t new_bytes);

}  // namespace meshedit::page_memory
