// How far this machine's memory bandwidth lets more threads go: how long one thread, and then `threads` threads at
// once, take to read buffers much bigger than the caches. peer_bench times the two reads as jobs in the same rounds
// as ours on one and on several threads and prints them beside ours' ratio, as context: on a virtual machine whose
// neighbours share the host's memory channels, the reads' own ratio moves from run to run. It bounds a pass that
// streams; a pass that waits on memory latency (Loop, normals on a big mesh) can scale further. Measured, never
// assumed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

namespace meshedit::bench {

class MemoryReadProbe {
 public:
  // One buffer of `mib` MiB per thread, written once here so its pages are in place before any read is timed.
  explicit MemoryReadProbe(int threads, size_t mib = 256)
      : buffers_(size_t(std::max(threads, 1)), std::vector<uint64_t>((mib << 20) / sizeof(uint64_t), 1)),
        sums_(buffers_.size()) {}

  int threads() const { return int(buffers_.size()); }

  // The first thread reads its buffer.
  void read_on_one_thread() { read(0); }

  // Every thread reads its own buffer at the same time: threads() times the bytes of read_on_one_thread.
  void read_on_all_threads() {
    std::vector<std::thread> others;
    for (size_t t = 1; t < buffers_.size(); ++t) others.emplace_back([this, t] { read(t); });
    read(0);
    for (std::thread& other : others) other.join();
  }

  // How many times the bytes per ms all threads read against one, from the two reads' times.
  double scaling(double one_thread_ms, double all_threads_ms) const {
    return double(threads()) * one_thread_ms / all_threads_ms;
  }

  // GB/s of the one-thread read and of the all-threads read (summed over the threads) from their times.
  double one_thread_gbs(double ms) const { return gb_per_buffer() / ms * 1e3; }
  double all_threads_gbs(double ms) const { return gb_per_buffer() * double(threads()) / ms * 1e3; }

 private:
  double gb_per_buffer() const { return double(buffers_[0].size() * sizeof(uint64_t)) / 1e9; }

  void read(size_t t) {
    uint64_t sum = 0;
    for (uint64_t word : buffers_[t]) sum += word;
    sums_[t] = sum;  // kept, so the reads are not optimised away
  }

  std::vector<std::vector<uint64_t>> buffers_;
  std::vector<uint64_t> sums_;
};

}  // namespace meshedit::bench
