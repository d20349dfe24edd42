// The seam between the runs of triangle rows (triangle_rows.h): which vertices more than one run touches.
//
// Invariant: the kept seam is always the one for its run count and vertex count over these rows, which never change;
// it is replaced whole under the mutex, and callers hold their own reference, so a caller never sees it half made.
#include "core/triangle_rows.h"

#include <vector>

#include "core/parallel_for.h"

namespace meshedit {

namespace {

// The seam made from scratch: each run marks the vertices its rows touch, then a vertex is on the seam where two
// runs' marks meet.
VertexBits make_seam(const TriangleRows& rows, int threads, size_t vertices) {
  const size_t words = (vertices + 63) / 64, runs = chunk_count(threads, rows.size());
  VertexBits seam;
  if (runs <= 1) {
    seam.assign(words, 0);
    return seam;
  }
  std::vector<VertexBits> touched(runs);
  parallel_chunks(threads, rows.size(), [&](size_t run, size_t begin, size_t end) {
    VertexBits& bits = touched[run];
    bits.assign(words, 0);
    for (size_t r = begin; r < end; ++r) {
      for (VertexId c : rows[r].corner) set_vertex_bit(bits.data(), c);
    }
  });
  seam.resize_for_overwrite(words);
  parallel_for(threads, words, [&](size_t begin, size_t end) {
    for (size_t w = begin; w < end; ++w) {
      uint64_t seen = 0, more_than_once = 0;
      for (const VertexBits& bits : touched) {
        more_than_once |= seen & bits[w];
        seen |= bits[w];
      }
      seam[w] = more_than_once;
    }
  });
  return seam;
}

}  // namespace

std::shared_ptr<const VertexBits> TriangleRows::seam_between_runs(int threads, size_t vertices) const {
  const size_t runs = chunk_count(threads, size());
  {
    const std::lock_guard<std::mutex> lock(seam_mutex_);
    if (seam_.bits && seam_.runs == runs && seam_.vertices == vertices) return seam_.bits;
  }
  // Made outside the lock: a second thread asking at the same time makes its own, and the last one made is kept.
  auto bits = std::make_shared<const VertexBits>(make_seam(*this, threads, vertices));
  const std::lock_guard<std::mutex> lock(seam_mutex_);
  seam_ = Seam{runs, vertices, bits};
  return bits;
}

size_t TriangleRows::memory_bytes() const {
  const std::lock_guard<std::mutex> lock(seam_mutex_);
  return capacity() * sizeof(TriangleRow) + (seam_.bits ? seam_.bits->capacity() * sizeof(uint64_t) : 0);
}

}  // namespace meshedit
