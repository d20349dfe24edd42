// FailingAllocations (failing_allocations.h): the replaced global operator new and delete of the binary that links
// this file, and the per-thread state they consult. Allocation is malloc, release is free. Every unaligned form is
// replaced, the nothrow ones included, so no memory from another operator new reaches this free().
#include "support/failing_allocations.h"

#include <cstdlib>
#include <new>

namespace {

// Constant-initialised, so operator new may read it from the first allocation of any thread on.
struct ArmedState {
  bool armed = false;
  bool fail_later = false;
  size_t nth = 0;
  size_t count = 0;
  size_t failures = 0;
};
thread_local ArmedState armed_state;

}  // namespace

void* operator new(std::size_t size) {
  ArmedState& s = armed_state;
  if (s.armed) {
    ++s.count;
    if (s.count == s.nth || (s.fail_later && s.count > s.nth)) {
      ++s.failures;
      throw std::bad_alloc();
    }
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return ::operator new(size); }
// The nothrow forms too (std::stable_sort's temporary buffer uses them): libstdc++'s own forms call the one above,
// but a sanitizer runtime brings its own, whose memory the operator delete below would then free() as if it were ours.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return ::operator new(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return ::operator new(size, tag); }
// GCC cannot see that the replaced operator new above uses malloc, so it warns about free() here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace meshedit::testing {

FailingAllocations::FailingAllocations(size_t nth, Later later) {
  armed_state = ArmedState{true, later == Later::Fail, nth, 0, 0};
}

FailingAllocations::~FailingAllocations() { armed_state.armed = false; }

bool FailingAllocations::failed() const { return armed_state.failures > 0; }

size_t FailingAllocations::allocations() const { return armed_state.count; }

}  // namespace meshedit::testing
