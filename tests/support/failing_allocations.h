// FailingAllocations: runs out of memory on demand, at any allocation, to test what code does there. While one is
// alive, the Nth allocation through the global operator new after it was made throws std::bad_alloc, and so does
// every later one when asked (Later::Fail: memory stays short) or none (Later::Succeed: one allocation fails).
// Looping N = 1, 2, ... until failed() stays false runs an operation out of memory at every allocation it makes.
//
// Invariants: deterministic, because only the allocations of the thread that made it count and fail (other threads
// never fail); one at a time per thread; aligned and mmap'd allocations are not counted. It works only in a binary
// that links failing_allocations.cpp, which replaces operator new and delete (the out_of_memory_tests binary alone,
// so no other test pays for it or can be failed by it).
#pragma once

#include <cstddef>

namespace meshedit::testing {

class FailingAllocations {
 public:
  enum class Later { Succeed, Fail };  // what the allocations after the Nth do

  FailingAllocations(size_t nth, Later later);
  ~FailingAllocations();  // disarms
  FailingAllocations(const FailingAllocations&) = delete;
  FailingAllocations& operator=(const FailingAllocations&) = delete;

  bool failed() const;         // whether an allocation was made to fail
  size_t allocations() const;  // allocations asked for since it was made, the failed ones included
};

}  // namespace meshedit::testing
