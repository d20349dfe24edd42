// MeshArray<T>: the storage of every per-element array of HalfedgeMesh (and of the renderer's slot arrays): a
// vector of trivially copyable elements on big_blocks (big_blocks.h), so on Linux an array of 4 MiB or more lives on
// huge pages and grows by moving its pages rather than copying its bytes (elsewhere: the C heap, page_memory.h).
//
// It offers the part of std::vector the mesh uses, with the same meaning, plus resize_for_overwrite(n): new
// elements whose bytes are left unset, for a pass that writes every one of them before any is read (fresh pages are
// then first touched by that pass, on its threads, and no value-initialising loop runs before it).
//
// Invariants: size() <= capacity(); data() is null exactly when capacity() is 0; the block holds capacity()
// elements and came from big_blocks with that many bytes. Growth asks for max(n, 2 * size()) elements, as
// std::vector does, so appends are amortised O(1). Out of memory: the rule of docs/ARCHITECTURE.md (Memory running
// out), size, capacity and contents included; moves and swaps never throw. Copies get exactly size() elements of
// capacity.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <type_traits>
#include <utility>

#include "core/big_blocks.h"

namespace meshedit {

template <class T>
class MeshArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "MeshArray moves its elements as bytes");

 public:
  using value_type = T;
  using size_type = size_t;
  using iterator = T*;
  using const_iterator = const T*;
  using reference = T&;
  using const_reference = const T&;

  MeshArray() = default;
  explicit MeshArray(size_t n) { resize(n); }
  MeshArray(size_t n, const T& value) { resize(n, value); }
  MeshArray(std::initializer_list<T> values) {
    resize_for_overwrite(values.size());
    std::copy(values.begin(), values.end(), data_);
  }
  MeshArray(const MeshArray& from) {
    if (from.size_ == 0) return;
    data_ = static_cast<T*>(big_blocks::allocate(bytes(from.size_)));
    std::memcpy(data_, from.data_, bytes(from.size_));
    size_ = capacity_ = from.size_;
  }
  MeshArray(MeshArray&& from) noexcept
      : data_(std::exchange(from.data_, nullptr)),
        size_(std::exchange(from.size_, 0)),
        capacity_(std::exchange(from.capacity_, 0)) {}
  // Reuses this array's block when it is big enough, as std::vector does; otherwise the copy gets a new one first.
  MeshArray& operator=(const MeshArray& from) {
    if (this == &from) return *this;
    if (from.size_ > capacity_) {
      MeshArray copy(from);
      swap(copy);
      return *this;
    }
    if (from.size_) std::memcpy(data_, from.data_, bytes(from.size_));
    size_ = from.size_;
    return *this;
  }
  MeshArray& operator=(MeshArray&& from) noexcept {
    if (this != &from) {
      MeshArray taken(std::move(from));
      swap(taken);
    }
    return *this;
  }
  ~MeshArray() { big_blocks::release(data_, bytes(capacity_)); }

  void swap(MeshArray& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

  size_t size() const { return size_; }
  size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

  void reserve(size_t n) {
    if (n > capacity_) regrow(n);
  }

  // Size n; new elements are left with whatever bytes the memory held (see the header comment).
  void resize_for_overwrite(size_t n) {
    if (n > capacity_) regrow(std::max(n, 2 * size_));
    size_ = n;
  }
  void resize(size_t n) { resize(n, T()); }
  void resize(size_t n, const T& value) {
    const size_t old = size_;
    if (n > capacity_) {
      const T copy = value;  // `value` may be an element of this array
      resize_for_overwrite(n);
      std::fill(data_ + old, data_ + n, copy);
      return;
    }
    if (n > old) std::fill(data_ + old, data_ + n, value);
    size_ = n;
  }

  // Replaces the contents with n copies of value, or with [first, last) (forward iterators).
  void assign(size_t n, const T& value) {
    if (n > capacity_) {
      MeshArray filled(n, value);
      swap(filled);
      return;
    }
    const T copy = value;  // `value` may be an element of this array
    std::fill(data_, data_ + n, copy);
    size_ = n;
  }
  template <class It, class = decltype(*std::declval<It&>()++)>
  void assign(It first, It last) {
    const auto n = static_cast<size_t>(std::distance(first, last));
    if (n > capacity_) {
      MeshArray copied;
      copied.resize_for_overwrite(n);
      std::copy(first, last, copied.data_);
      swap(copied);
      return;
    }
    std::copy(first, last, data_);
    size_ = n;
  }

  void push_back(const T& value) {
    if (size_ == capacity_) {
      const T copy = value;  // `value` may be an element of this array
      regrow(std::max<size_t>(1, 2 * size_));
      data_[size_++] = copy;
      return;
    }
    data_[size_++] = value;
  }
  template <class... Args>
  T& emplace_back(Args&&... args) {
    push_back(T(std::forward<Args>(args)...));
    return back();
  }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }
  void shrink_to_fit() {
    if (capacity_ == size_) return;
    MeshArray exact(*this);
    swap(exact);
  }

  friend bool operator==(const MeshArray& a, const MeshArray& b) {
    return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
  }

 private:
  static size_t bytes(size_t n) { return n * sizeof(T); }

  void regrow(size_t n) {
    data_ = static_cast<T*>(big_blocks::regrow(data_, bytes(capacity_), bytes(size_), bytes(n)));
    capacity_ = n;
  }

  T* data_ = nullptr;
  size_t size_ = 0;
  size_t capacity_ = 0;
};

}  // namespace meshedit
