// AliveFlags: the `alive` flag of every slot of one element kind (HalfedgeMesh), stored as dead bits that exist only
// once something of that kind has died.
//
// Why: a mesh that was built or subdivided has no dead slot, and that is the mesh that is big. There the flags take
// no memory and growing the kind writes nothing but the size; the mesh then holds exactly its explicit pointers and
// positions. After the first deletion of the kind, one bit per slot is kept (1 = dead).
//
// Invariants: size() is the slot count of the kind, whether or not bits exist; when bits exist they cover size()
// slots and every bit at or past size() is zero; "no bits" means "every slot alive". Equality is by value (a mesh
// whose dead slots came back to life equals one that never had bits). Not safe to write from two threads at once.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshedit {

class AliveFlags {
 public:
  AliveFlags() = default;
  AliveFlags(const AliveFlags&) = default;
  AliveFlags& operator=(const AliveFlags&) = default;
  // A moved-from AliveFlags is empty, like the mesh's other arrays (capacities are read from size()).
  AliveFlags(AliveFlags&& from) noexcept : size_(std::exchange(from.size_, 0)), dead_(std::move(from.dead_)) {
    from.dead_.clear();
  }
  AliveFlags& operator=(AliveFlags&& from) noexcept {
    size_ = std::exchange(from.size_, 0);
    dead_ = std::move(from.dead_);
    from.dead_.clear();
    return *this;
  }

  size_t size() const { return size_; }

  // Precondition: i < size().
  bool operator[](size_t i) const { return dead_.empty() || ((dead_[i >> 6] >> (i & 63)) & 1) == 0; }

  void set(size_t i, bool alive) {
    if (alive) {
      if (!dead_.empty()) dead_[i >> 6] &= ~bit(i);
      return;
    }
    materialise();
    dead_[i >> 6] |= bit(i);
  }

  void push_back(bool alive) { resize(size_ + 1, alive); }

  // New slots (past the old size) take `alive`; slots past `n` are dropped.
  void resize(size_t n, bool alive) {
    const size_t old = size_;
    if (n <= old) {
      size_ = n;
      if (!dead_.empty()) {
        dead_.resize(words(n));
        if (n & 63) dead_.back() &= bit(n) - 1;
      }
      return;
    }
    if (alive && dead_.empty()) {
      size_ = n;
      return;
    }
    materialise();
    dead_.resize(words(n), 0);  // before size_: out of memory here leaves the flags as they were
    size_ = n;
    if (!alive)
      for (size_t i = old; i < n; ++i) dead_[i >> 6] |= bit(i);
  }

  void assign(size_t n, bool alive) {
    size_ = 0;
    dead_.clear();
    resize(n, alive);
  }

  // Makes room for this many slots of dead bits, when bits exist (none are needed otherwise).
  void reserve(size_t n) {
    if (!dead_.empty()) dead_.reserve(words(n));
  }
  // Makes room for dead bits of up to n slots, creating the bits if there are none yet (the value stays: all alive):
  // afterwards resize() and set() up to n slots allocate nothing.
  void reserve_bits(size_t n) {
    materialise();
    dead_.reserve(words(std::max(n, size_)));
  }

  // Bytes held (capacity of the bits).
  size_t memory_bytes() const { return dead_.capacity() * sizeof(uint64_t); }

  friend bool operator==(const AliveFlags& a, const AliveFlags& b) {
    if (a.size_ != b.size_) return false;
    if (a.dead_.empty() || b.dead_.empty()) return a.no_bit_set() && b.no_bit_set();
    return a.dead_ == b.dead_;
  }

 private:
  static size_t words(size_t n) { return (n + 63) >> 6; }
  static uint64_t bit(size_t i) { return uint64_t(1) << (i & 63); }
  void materialise() {
    if (dead_.empty() && size_ > 0) dead_.assign(words(size_), 0);
  }
  bool no_bit_set() const {
    for (uint64_t w : dead_)
      if (w) return false;
    return true;
  }

  size_t size_ = 0;
  std::vector<uint64_t> dead_;  // bit i of word i / 64 set = slot i dead; empty = all alive
};

}  // namespace meshedit
