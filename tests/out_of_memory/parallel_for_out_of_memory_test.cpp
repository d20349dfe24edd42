// parallel_chunks and parallel_for when threads cannot be started (FailingAllocations fails each allocation of the
// call in turn, among them every std::thread's) and when a chunk throws: every chunk (block) still runs exactly
// once, or none does when the failure comes before the first; the exception reaches the caller after every chunk
// has finished; nothing terminates.
#include <atomic>
#include <new>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/parallel_for.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;

constexpr int kThreads = 4;
constexpr size_t kItems = 4 * kMinItemsPerThread;  // four chunks

TEST(ParallelForOutOfMemory, EveryChunkRunsOnceWhenThreadsCannotStart) {
  for (const auto later : {FailingAllocations::Later::Succeed, FailingAllocations::Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      std::vector<std::atomic<int>> runs(kItems);
      bool threw = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          parallel_chunks(kThreads, kItems, [&](size_t, size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) runs[i].fetch_add(1);
          });
        } catch (const std::bad_alloc&) {
          threw = true;
        }
        failed = failing.failed();
      }
      size_t once = 0, never = 0;
      for (const std::atomic<int>& r : runs) {
        once += r.load() == 1;
        never += r.load() == 0;
      }
      if (threw) {
        EXPECT_EQ(never, kItems);  // failed before any chunk started
      } else {
        EXPECT_EQ(once, kItems);
      }
      if (!failed) {
        EXPECT_GT(n, 3u);  // at least the three threads' allocations were failed in turn
        break;
      }
    }
  }
}

TEST(ParallelForOutOfMemory, EveryBlockRunsOnceWhenThreadsCannotStart) {
  for (size_t n = 1;; ++n) {
    SCOPED_TRACE(n);
    std::vector<std::atomic<int>> runs(kItems);
    bool threw = false, failed = false;
    {
      const FailingAllocations failing(n, FailingAllocations::Later::Fail);
      try {
        parallel_for(kThreads, kItems, [&](size_t begin, size_t end) {
          for (size_t i = begin; i < end; ++i) runs[i].fetch_add(1);
        });
      } catch (const std::bad_alloc&) {
        threw = true;
      }
      failed = failing.failed();
    }
    size_t once = 0;
    for (const std::atomic<int>& r : runs) once += r.load() == 1;
    EXPECT_EQ(once, threw ? 0u : kItems);
    if (!failed) break;
  }
}

TEST(ParallelForOutOfMemory, AChunkThatThrowsReachesTheCallerAfterTheOthersFinish) {
  for (size_t throwing = 0; throwing < 4; ++throwing) {
    SCOPED_TRACE(throwing);
    std::vector<std::atomic<int>> runs(kItems);
    try {
      parallel_chunks(kThreads, kItems, [&](size_t chunk, size_t begin, size_t end) {
        if (chunk == throwing) throw std::runtime_error("chunk " + std::to_string(chunk));
        for (size_t i = begin; i < end; ++i) runs[i].fetch_add(1);
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(std::string(error.what()), "chunk " + std::to_string(throwing));
    }
    for (size_t c = 0; c < 4; ++c) {
      const size_t begin = chunk_begin(c, 4, kItems), end = chunk_begin(c + 1, 4, kItems);
      for (size_t i = begin; i < end; ++i) ASSERT_EQ(runs[i].load(), c == throwing ? 0 : 1) << i;
    }
  }
}

}  // namespace
}  // namespace meshedit
