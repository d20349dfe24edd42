// Reading and writing fixed-size numbers in a byte string in either byte order, for the binary PLY and
// STL readers and writers. Values are assembled byte by byte, so the host's byte order and alignment
// never matter.
//
// Invariant: load_* reads exactly sizeof(T) bytes at `at`; callers check that they exist first.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace meshedit {

enum class ByteOrder { Little, Big };

inline uint64_t load_unsigned(std::string_view bytes, size_t at, size_t size, ByteOrder order) {
  uint64_t value = 0;
  for (size_t i = 0; i < size; ++i) {
    const size_t index = order == ByteOrder::Little ? at + size - 1 - i : at + i;
    value = (value << 8) | static_cast<unsigned char>(bytes[index]);
  }
  return value;
}

inline float load_float(std::string_view bytes, size_t at, ByteOrder order) {
  const auto bits = static_cast<uint32_t>(load_unsigned(bytes, at, 4, order));
  float value = 0;
  std::memcpy(&value, &bits, 4);
  return value;
}

inline double load_double(std::string_view bytes, size_t at, ByteOrder order) {
  const uint64_t bits = load_unsigned(bytes, at, 8, order);
  double value = 0;
  std::memcpy(&value, &bits, 8);
  return value;
}

inline void append_unsigned_le(std::string& out, uint64_t value, size_t size) {
  for (size_t i = 0; i < size; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

inline void append_float_le(std::string& out, float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  append_unsigned_le(out, bits, 4);
}

inline void append_double_le(std::string& out, double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, 8);
  append_unsigned_le(out, bits, 8);
}

}  // namespace meshedit
