// parallel_for, parallel_chunks and parallel_stripes (parallel_for.h): every index is handed out exactly once, in
// ranges that lie inside [0, n), for thread counts and sizes around the points where the split changes;
// parallel_chunks' chunks are the documented fixed ranges, parallel_stripes' the documented interleaved blocks; all
// return only when every range is done.
#include "core/parallel_for.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

namespace meshedit {
namespace {

const size_t kSizes[] = {0,
                         1,
                         kMinItemsPerThread - 1,
                         kMinItemsPerThread * 2,
                         kMinItemsPerThread * 2 + 1,
                         kMinItemsPerThread * 17 + 5,
                         kMinItemsPerThread * 80 + 3};

TEST(ParallelFor, HandsOutEveryIndexExactlyOnce) {
  for (const int threads : {0, 1, 2, 3, 8}) {
    for (const size_t n : kSizes) {
      auto seen = std::make_unique<std::atomic<uint8_t>[]>(n);
      for (size_t i = 0; i < n; ++i) seen[i] = 0;
      std::atomic<size_t> calls{0};
      parallel_for(threads, n, [&](size_t begin, size_t end) {
        ASSERT_LE(begin, end);
        ASSERT_LE(end, n);
        ++calls;
        for (size_t i = begin; i < end; ++i) seen[i].fetch_add(1);
      });
      for (size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "index " << i << " of " << n << ", " << threads;
      // A small range is one plain call; a big one with several threads is cut into kBlocksPerThread blocks per
      // thread, so a thread that finishes early takes work from the rest.
      const size_t chunks = chunk_count(threads, n);
      if (chunks <= 1) {
        EXPECT_EQ(calls.load(), 1u) << n << ", " << threads;
      } else if (n >= chunks * kBlocksPerThread * kMinItemsPerThread) {
        EXPECT_EQ(calls.load(), chunks * kBlocksPerThread) << n << ", " << threads;
      } else {
        EXPECT_GE(calls.load(), chunks) << n << ", " << threads;
      }
    }
  }
}

TEST(ParallelFor, RunsOnSeveralThreadsWhenAsked) {
  std::mutex mutex;
  std::set<std::thread::id> ids;
  parallel_for(2, kMinItemsPerThread * 80, [&](size_t, size_t) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // long enough that the other thread takes a block
    const std::lock_guard<std::mutex> lock(mutex);
    ids.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(ids.size(), 2u);
}

TEST(ParallelChunks, ChunksAreTheDocumentedFixedRanges) {
  for (const int threads : {1, 2, 3}) {
    for (const size_t n : kSizes) {
      const size_t chunks = chunk_count(threads, n);
      std::mutex mutex;
      std::set<std::pair<size_t, size_t>> ranges;
      std::set<size_t> chunk_ids;
      parallel_chunks(threads, n, [&](size_t chunk, size_t begin, size_t end) {
        const std::lock_guard<std::mutex> lock(mutex);
        chunk_ids.insert(chunk);
        EXPECT_EQ(begin, chunk_begin(chunk, chunks, n));
        EXPECT_EQ(end, chunk_begin(chunk + 1, chunks, n));
        ranges.insert({begin, end});
      });
      EXPECT_EQ(chunk_ids.size(), chunks) << n << ", " << threads;
      size_t covered = 0;
      for (const auto& [begin, end] : ranges) {
        EXPECT_EQ(begin, covered);
        covered = end;
      }
      EXPECT_EQ(covered, n);
    }
  }
}

TEST(ParallelStripes, ChunkCTakesEveryChunksThBlockInOrder) {
  for (const int threads : {0, 1, 2, 3, 8}) {
    for (const size_t n : kSizes) {
      const size_t chunks = chunk_count(threads, n), blocks = stripe_blocks(chunks, n);
      ASSERT_GE(blocks, chunks);
      std::mutex mutex;
      std::vector<std::vector<std::pair<size_t, size_t>>> taken(chunks);
      parallel_stripes(threads, n, [&](size_t chunk, size_t begin, size_t end) {
        const std::lock_guard<std::mutex> lock(mutex);
        ASSERT_LT(chunk, chunks);
        taken[chunk].push_back({begin, end});
      });
      // Chunk c ran blocks c, c + chunks, ... in that order; together the blocks tile [0, n) with no gap.
      std::vector<std::pair<size_t, size_t>> all;
      for (size_t c = 0; c < chunks; ++c) {
        size_t b = c;
        for (const auto& range : taken[c]) {
          EXPECT_EQ(range, std::make_pair(chunk_begin(b, blocks, n), chunk_begin(b + 1, blocks, n))) << n;
          b += chunks;
        }
        EXPECT_GE(b, blocks) << "chunk " << c << " missed a block of " << n;
        all.insert(all.end(), taken[c].begin(), taken[c].end());
      }
      std::sort(all.begin(), all.end());
      size_t covered = 0;
      for (const auto& [begin, end] : all) {
        EXPECT_EQ(begin, covered);
        covered = end;
      }
      EXPECT_EQ(covered, n) << threads;
      // A big range gives every chunk blocks from its start, its middle and its end.
      if (n >= kMinItemsPerThread * 80 && chunks > 1) {
        EXPECT_EQ(blocks, chunks * kStripesPerChunk);
      }
    }
  }
}

}  // namespace
}  // namespace meshedit
