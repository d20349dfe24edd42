// BinaryBuilder: bytes of a binary test file (PLY bodies, binary STL) written value by value in a chosen
// byte order, so fixtures read like the files they imitate.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace meshedit::testing {

class BinaryBuilder {
 public:
  explicit BinaryBuilder(bool big_endian = false, std::string start = "")
      : big_(big_endian), bytes_(std::move(start)) {}

  BinaryBuilder& u8(uint8_t v) { return put(v, 1); }
  BinaryBuilder& i8(int8_t v) { return put(static_cast<uint8_t>(v), 1); }
  BinaryBuilder& u16(uint16_t v) { return put(v, 2); }
  BinaryBuilder& i16(int16_t v) { return put(static_cast<uint16_t>(v), 2); }
  BinaryBuilder& u32(uint32_t v) { return put(v, 4); }
  BinaryBuilder& i32(int32_t v) { return put(static_cast<uint32_t>(v), 4); }
  BinaryBuilder& f32(float v) {
    uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    return put(bits, 4);
  }
  BinaryBuilder& f64(double v) {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, 8);
    return put(bits, 8);
  }
  BinaryBuilder& text(const std::string& s) {
    bytes_ += s;
    return *this;
  }

  const std::string& bytes() const { return bytes_; }

 private:
  BinaryBuilder& put(uint64_t value, size_t size) {
    for (size_t i = 0; i < size; ++i) {
      const size_t shift = big_ ? 8 * (size - 1 - i) : 8 * i;
      bytes_ += static_cast<char>((value >> shift) & 0xff);
    }
    return *this;
  }

  bool big_;
  std::string bytes_;
};

}  // namespace meshedit::testing
