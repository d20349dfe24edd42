// Building glTF and GLB files by hand for the tests: base64, packed little-endian arrays, a .gltf with
// one embedded buffer, a .glb with its chunks, and a small indexed square used by several tests.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace meshedit::testing {

inline std::string base64(const std::string& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(n >> s) & 63];
  }
  if (i < bytes.size()) {
    uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) n |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// Little-endian bytes of a list of values, padded to 4 bytes.
template <class T>
inline std::string bytes_of(const std::vector<T>& values) {
  std::string out(values.size() * sizeof(T), '\0');
  std::memcpy(out.data(), values.data(), out.size());
  while (out.size() % 4 != 0) out += '\0';
  return out;
}

// A .gltf document: `body` (JSON members without the braces) plus an asset and one embedded buffer.
inline std::string gltf(const std::string& body, const std::string& buffer) {
  return "{\"asset\":{\"version\":\"2.0\"}," + body + ",\"buffers\":[{\"byteLength\":" + std::to_string(buffer.size()) +
         ",\"uri\":\"data:application/octet-stream;base64," + base64(buffer) + "\"}]}";
}

// A .glb with the given JSON and binary chunk (both padded as the format requires).
inline std::string glb(std::string json, std::string bin) {
  while (json.size() % 4 != 0) json += ' ';
  while (bin.size() % 4 != 0) bin += '\0';
  const auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const uint32_t total = 12 + 8 + uint32_t(json.size()) + (bin.empty() ? 0 : 8 + uint32_t(bin.size()));
  std::string out = "glTF" + u32(2) + u32(total) + u32(uint32_t(json.size())) + "JSON" + json;
  if (!bin.empty()) out += u32(uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
  return out;
}

// Four corners of a unit square, interleaved with 4 padding bytes each (byteStride 16), then uint16
// indices of two triangles.
inline const std::string kSquareBuffer = [] {
  std::string b = bytes_of(std::vector<float>{0, 0, 0, -1, 1, 0, 0, -1, 1, 1, 0, -1, 0, 1, 0, -1});
  return b + bytes_of(std::vector<uint16_t>{0, 1, 2, 0, 2, 3});
}();
inline const std::string kSquareParts =
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
    "{\"bufferView\":1,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":64,\"byteStride\":16},"
    "{\"buffer\":0,\"byteOffset\":64,\"byteLength\":12}]";

}  // namespace meshedit::testing
