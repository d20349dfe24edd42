// What every benchmark program needs: the minimum wall time over repeated runs, and reading a numeric
// option from the command line. Benchmarks print numbers; nothing here asserts a time.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>

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

// The number after `name` on the command line (`--reps 5`), or `fallback`.
inline long arg(int argc, char** argv, const char* name, long fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return std::strtol(argv[i + 1], nullptr, 10);
  }
  return fallback;
}

}  // namespace meshedit::bench
