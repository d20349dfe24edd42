// memory_hints: the cache hints whole-mesh passes give the processor, in one place. Each is a hint only: a build
// for a processor or compiler without it does the same work without the hint, and no result depends on them.
//
// - prefetch, prefetch_for_write: start loading the line at p (to read it, or to write it soon).
// - prefetch_record: a halfedge record is 20 bytes, so one record in four spans two cache lines; this fetches both.
// - stream_store: writes 16 bytes that the pass will not read again soon past the caches (x86's non-temporal store),
//   so writing a long output array does not first read every line of it. Callers write whole 64-byte lines, in
//   order, and call stream_fence() before another thread or pass reads what they wrote.
#pragma once

#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/halfedge_mesh.h"

namespace meshedit::memory_hints {

inline void prefetch(const void* p) { __builtin_prefetch(p); }
inline void prefetch_for_write(const void* p) { __builtin_prefetch(p, 1); }

inline void prefetch_record(const HalfedgeRecord* r) {
  __builtin_prefetch(r);
  __builtin_prefetch(reinterpret_cast<const char*>(r + 1) - 1);
}

// Writes the 16 bytes at `from` to `to` (16-byte aligned).
inline void stream_store(void* to, const void* from) {
#if defined(__SSE2__)
  _mm_stream_si128(static_cast<__m128i*>(to), _mm_loadu_si128(static_cast<const __m128i*>(from)));
#else
  std::memcpy(to, from, 16);
#endif
}

inline void stream_fence() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

}  // namespace meshedit::memory_hints
