// parallel_chunks / parallel_for: run a function over [0, n) on up to `threads` threads, one std::thread per chunk
// beyond the first (which runs on the caller). With threads <= 1 or a small n it is a plain call.
//
// Invariants: every index in [0, n) is handed out exactly once, and the call returns only after all of them are
// done, so a pass that writes disjoint elements per index needs no other synchronisation.
// - parallel_chunks: chunk c covers [chunk_begin(c), chunk_begin(c + 1)) and is run by one thread; chunk_count()
//   tells how many chunks a call with the same (threads, n) makes, for passes that keep one partial result per
//   chunk (prefix sums, per-thread sums). The split depends on (threads, n) only, so such results are
//   deterministic.
// - parallel_stripes: the same fixed chunks, one per thread, each made of every chunks-th block of [0, n) (block c,
//   c + chunks, c + 2 * chunks, ...), so each thread gets its share of the slow and the fast parts of a mesh while
//   its partial result still depends on (threads, n) only.
// - parallel_for: the range is cut into kBlocksPerThread blocks per thread, in index order, and each thread takes
//   the next block not yet taken. On a mesh the cost per index is uneven (old elements' neighbours lie further
//   apart than new ones'), and fixed halves left one thread waiting for the other for up to a third of a pass. Which
//   thread runs a block varies from run to run, so the function must compute each index independently.
// - Nothing here ends the program: a chunk whose thread cannot start (out of memory, out of threads) runs on the
//   caller, and an exception thrown by any chunk reaches the caller after every chunk has finished (the first one,
//   by chunk order, when several throw).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace meshedit {

// Below this many items per chunk a pass is not split: starting a thread costs more than the work.
inline constexpr size_t kMinItemsPerThread = 16384;

// The machine's cores, at least 1: the threads a whole-mesh pass started by the user (L in the window, `meshedit
// subdivide`, the renderer's build) runs on, and the default number of `meshedit grade` jobs. 1 in a build without
// threads (MESHEDIT_ONE_THREAD: the web page, engine/core/CMakeLists.txt), where no std::thread can start.
inline int hardware_threads() {
#if defined(MESHEDIT_ONE_THREAD)
  return 1;
#else
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : static_cast<int>(cores);
#endif
}

inline size_t chunk_count(int threads, size_t n) {
  return std::clamp<size_t>(threads < 1 ? 1 : size_t(threads), 1, std::max<size_t>(1, n / kMinItemsPerThread));
}

inline size_t chunk_begin(size_t chunk, size_t chunks, size_t n) { return n * chunk / chunks; }

// fn(chunk, begin, end) for each of chunk_count(threads, n) chunks.
template <class Fn>
void parallel_chunks(int threads, size_t n, Fn&& fn) {
  const size_t chunks = chunk_count(threads, n);
  if (chunks <= 1) {
    fn(size_t(0), size_t(0), n);
    return;
  }
  // Both allocated before any thread starts: if either fails, nothing has run yet.
  std::vector<std::exception_ptr> errors(chunks);
  std::vector<std::thread> workers;
  workers.reserve(chunks - 1);
  auto run = [&fn, &errors, chunks, n](size_t c) noexcept {
    try {
      fn(c, chunk_begin(c, chunks, n), chunk_begin(c + 1, chunks, n));
    } catch (...) {
      errors[c] = std::current_exception();
    }
  };
  size_t started = 1;
  for (; started < chunks; ++started) {
    try {
      workers.emplace_back(run, started);
    } catch (...) {
      break;  // this chunk and the ones after it run here, below
    }
  }
  run(0);
  for (size_t c = started; c < chunks; ++c) run(c);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

// Blocks per chunk in parallel_stripes: enough that each chunk samples the whole range evenly.
inline constexpr size_t kStripesPerChunk = 32;

// How many blocks parallel_stripes cuts [0, n) into for `chunks` chunks: kStripesPerChunk per chunk, but no block
// under kMinItemsPerThread / 4 items, and at least one per chunk.
inline size_t stripe_blocks(size_t chunks, size_t n) {
  return std::max(chunks, std::min(chunks * kStripesPerChunk, n / (kMinItemsPerThread / 4)));
}

// fn(chunk, begin, end) for every block of chunk `chunk`, in index order, on that chunk's thread; chunks as
// chunk_count(threads, n) gives them.
template <class Fn>
void parallel_stripes(int threads, size_t n, Fn&& fn) {
  const size_t chunks = chunk_count(threads, n), blocks = stripe_blocks(chunks, n);
  parallel_chunks(threads, n, [&](size_t chunk, size_t, size_t) {
    for (size_t b = chunk; b < blocks; b += chunks) fn(chunk, chunk_begin(b, blocks, n), chunk_begin(b + 1, blocks, n));
  });
}

inline constexpr size_t kBlocksPerThread = 8;

// fn(begin, end) for blocks covering [0, n), taken by the threads in turn.
template <class Fn>
void parallel_for(int threads, size_t n, Fn&& fn) {
  const size_t chunks = chunk_count(threads, n);
  if (chunks <= 1) {
    fn(size_t(0), n);
    return;
  }
  const size_t blocks = std::min(chunks * kBlocksPerThread, std::max<size_t>(chunks, n / kMinItemsPerThread));
  std::atomic<size_t> next_block{0};
  parallel_chunks(threads, n, [&](size_t, size_t, size_t) {
    for (size_t b = next_block.fetch_add(1, std::memory_order_relaxed); b < blocks;
         b = next_block.fetch_add(1, std::memory_order_relaxed)) {
      fn(chunk_begin(b, blocks, n), chunk_begin(b + 1, blocks, n));
    }
  });
}

}  // namespace meshedit
