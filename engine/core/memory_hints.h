// memory_hints: the cache hints whole-mesh passes give the processor, in one place. Each is a hint only: a build
// for a processor or compiler without it does the same work without the hint, and no result depends on them. The
// builtins and intrinsics underneath are compiler_builtins.h's.
//
// - prefetch, prefetch_for_write: start loading the line at p (to read it, or to write it soon).
// - prefetch_record: a halfedge record is 20 bytes, so one record in four spans two cache lines; this fetches both.
// - stream_store: writes 16 bytes that the pass will not read again soon past the caches (x86's non-temporal store),
//   so writing a long output array does not first read every line of it. Callers write whole 64-byte lines, in
//   order, and call stream_fence() before another thread or pass reads what they wrote.
#pragma once

#include <cstring>

#include "core/compiler_builtins.h"
#include "core/halfedge_mesh.h"

namespace meshedit::memory_hints {

inline void prefetch(const void* p) { MESHEDIT_PREFETCH(p); }
inline void prefetch_for_write(const void* p) { MESHEDIT_PREFETCH_FOR_WRITE(p); }

inline void prefetch_record(const HalfedgeRecord* r) {
  MESHEDIT_PREFETCH(r);
  MESHEDIT_PREFETCH(reinterpret_cast<const char*>(r + 1) - 1);
}

// Writes the 16 bytes at `from` to `to` (16-byte aligned).
inline void stream_store(void* to, const void* from) {
#if MESHEDIT_HAS_STREAM_STORE
  MESHEDIT_STREAM_STORE_16(to, from);
#else
  std::memcpy(to, from, 16);
#endif
}

inline void stream_fence() {
#if MESHEDIT_HAS_STREAM_STORE
  MESHEDIT_STREAM_FENCE();
#endif
}

}  // namespace meshedit::memory_hints
