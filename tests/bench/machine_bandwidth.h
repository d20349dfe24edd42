// How far this machine's memory lets more threads go: the rate at which one thread, and then `threads` threads at
// once, read a buffer much bigger than the caches. A pass that waits on memory (Loop, normals on a big mesh) can
// scale over threads only as far as this does, so peer_bench prints it beside its "N threads over one" lines.
// Measured, never assumed: on a machine with one memory channel per core the ratio is near the thread count, on a
// virtual machine sharing its host's channels it can be far below.
#pragma once

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

#include "bench/bench_support.h"

namespace meshedit::bench {

struct ReadRates {
  double one_thread_gbs = 0.0;
  double all_threads_gbs = 0.0;  // summed over the threads
};

// Each thread sums its own `mib`-MiB buffer; the best of `reps` runs, one thread and all threads interleaved.
inline ReadRates measure_read_rates(int threads, int reps, size_t mib = 256) {
  const size_t words = (mib << 20) / sizeof(uint64_t);
  std::vector<std::vector<uint64_t>> buffers(size_t(std::max(threads, 1)), std::vector<uint64_t>(words, 1));
  std::vector<uint64_t> sums(buffers.size());
  const auto read = [&](size_t t) {
    uint64_t sum = 0;
    for (uint64_t word : buffers[t]) sum += word;
    sums[t] = sum;  // kept, so the reads are not optimised away
  };
  const auto all = [&] {
    std::vector<std::thread> others;
    for (size_t t = 1; t < buffers.size(); ++t) others.emplace_back(read, t);
    read(0);
    for (std::thread& other : others) other.join();
  };
  double one_ms = 1e300, all_ms = 1e300;
  for (int i = 0; i < reps; ++i) {
    one_ms = std::min(one_ms, min_ms(
                                  1, [] {}, [&] { read(0); }));
    all_ms = std::min(all_ms, min_ms(
                                  1, [] {}, all));
  }
  const double gb = double(mib << 20) / 1e9;
  return {gb / one_ms * 1e3, gb * double(buffers.size()) / all_ms * 1e3};
}

}  // namespace meshedit::bench
