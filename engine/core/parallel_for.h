// parallel_for: runs a function over [0, n) split into contiguous chunks, one std::thread per chunk beyond the
// first (which runs on the caller). With threads <= 1 or a small n it is a plain call.
//
// Invariant: every index in [0, n) is in exactly one chunk; chunk c covers [chunk_begin(c), chunk_begin(c + 1)),
// chunks are in index order, and the call returns only after every chunk has finished, so a pass that writes
// disjoint elements per index needs no other synchronisation. chunk_count() tells how many chunks a call with the
// same (threads, n) makes, for passes that keep one partial result per chunk (prefix sums).
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace meshedit {

// Below this many items per chunk a pass is not split: starting a thread costs more than the work.
inline constexpr size_t kMinItemsPerThread = 16384;

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
  std::vector<std::thread> workers;
  workers.reserve(chunks - 1);
  for (size_t c = 1; c < chunks; ++c) {
    workers.emplace_back([&fn, c, n, chunks] { fn(c, chunk_begin(c, chunks, n), chunk_begin(c + 1, chunks, n)); });
  }
  fn(size_t(0), size_t(0), chunk_begin(1, chunks, n));
  for (std::thread& w : workers) w.join();
}

// fn(begin, end) for each chunk.
template <class Fn>
void parallel_for(int threads, size_t n, Fn&& fn) {
  parallel_chunks(threads, n, [&fn](size_t, size_t begin, size_t end) { fn(begin, end); });
}

}  // namespace meshedit
