// What every benchmark program needs: the minimum wall time over repeated runs, reading a numeric option
// from the command line, and backing physical memory before a timed run. Benchmarks print numbers; nothing
// here asserts a time.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>

#include <sys/mman.h>

namespace meshedit::bench {

// Minimum wall time of `reps` runs of `work`, in milliseconds; `setup` runs untimed before each.
inline double min_ms(int reps, const std::function<void()>& setup, const std::function<void()>& work) {
  double best = 1e300;
  for (int i = 0; i < reps; ++i) {
    setup();
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

// Touches `mib` MiB of fresh anonymous memory and unmaps it, so the next allocations of the process get
// physical pages the host has already backed.
//
// Why: this VM (Firecracker, free page reporting of 8 MiB blocks) hands memory that stays free for about
// two seconds back to the host, and touching such memory again costs host faults: 600 MB of huge pages
// took 1.1 s more in a fresh process than right after a previous run (3.7 ms per 2 MiB page). Whoever runs
// next after a long pause or after another contender's churn pays it, so without this the order of the
// jobs decides the table. Called right before every timed run of every contender, it gives all of them
// the freshly-zeroed but backed pages a machine without page reporting gives. Untimed.
inline void back_physical_memory(size_t mib) {
  const size_t bytes = mib << 20;
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return;
#ifdef MADV_HUGEPAGE
  madvise(p, bytes, MADV_HUGEPAGE);
#endif
  auto* memory = static_cast<volatile char*>(p);
  for (size_t i = 0; i < bytes; i += 4096) memory[i] = 1;
  munmap(p, bytes);
}

// The number after `name` on the command line (`--reps 5`), or `fallback`.
inline long arg(int argc, char** argv, const char* name, long fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return std::strtol(argv[i + 1], nullptr, 10);
  }
  return fallback;
}

}  // namespace meshedit::bench
