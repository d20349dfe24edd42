// compiler_builtins: every compiler builtin and processor intrinsic the engine uses, each behind one macro, so the
// rest of the code is standard C++ and a new compiler is taught here alone. On gcc and clang each macro is the builtin
// itself (the generated code is the builtin's); MSVC gets its own spelling; any other compiler gets a fallback that
// does the same work without the hint.
//
// - MESHEDIT_PREFETCH(p), MESHEDIT_PREFETCH_FOR_WRITE(p): start loading the cache line at p, to read it or to write
//   it soon. A hint: without it the same loads happen later.
// - MESHEDIT_UNREACHABLE(): this point is never reached (after a call that never returns). Where the compiler has
//   no such builtin the fallback stops the program.
// - MESHEDIT_HAS_STREAM_STORE: 1 where MESHEDIT_STREAM_STORE_16(to, from) writes the 16 bytes at `from` to `to`
//   (16-byte aligned) past the caches (x86's non-temporal store) and MESHEDIT_STREAM_FENCE() orders those stores
//   before what follows; 0 elsewhere, where neither macro is defined (memory_hints.h copies and needs no fence).
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define MESHEDIT_PREFETCH(p) __builtin_prefetch(p)
#define MESHEDIT_PREFETCH_FOR_WRITE(p) __builtin_prefetch(p, 1)
#define MESHEDIT_UNREACHABLE() __builtin_unreachable()
#elif defined(_MSC_VER)
#include <intrin.h>
#if defined(_M_X64) || defined(_M_IX86)
#define MESHEDIT_PREFETCH(p) _mm_prefetch(reinterpret_cast<const char*>(p), _MM_HINT_T0)
#define MESHEDIT_PREFETCH_FOR_WRITE(p) _mm_prefetch(reinterpret_cast<const char*>(p), _MM_HINT_T0)
#else
#define MESHEDIT_PREFETCH(p) static_cast<void>(p)
#define MESHEDIT_PREFETCH_FOR_WRITE(p) static_cast<void>(p)
#endif
#define MESHEDIT_UNREACHABLE() __assume(0)
#else
#include <cstdlib>
#define MESHEDIT_PREFETCH(p) static_cast<void>(p)
#define MESHEDIT_PREFETCH_FOR_WRITE(p) static_cast<void>(p)
#define MESHEDIT_UNREACHABLE() std::abort()
#endif

// SSE2: gcc and clang say so with __SSE2__; MSVC has it on every x64 target and on x86 with /arch:SSE2 or above.
#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#include <emmintrin.h>
#define MESHEDIT_HAS_STREAM_STORE 1
#define MESHEDIT_STREAM_STORE_16(to, from) \
  _mm_stream_si128(static_cast<__m128i*>(to), _mm_loadu_si128(static_cast<const __m128i*>(from)))
#define MESHEDIT_STREAM_FENCE() _mm_sfence()
#else
#define MESHEDIT_HAS_STREAM_STORE 0
#endif
