// PolygonMesh: indexed polygons, the exchange format between file readers, procedural shapes and the
// half-edge mesh (what `.obj`, COLLADA and glTF store, before any connectivity is known).
//
// Invariants kept by the methods (not by direct writes to the vectors):
// - `face_offsets` starts at 0, is non-decreasing, and its last entry equals `indices.size()`;
//   face i is `indices[face_offsets[i] .. face_offsets[i+1])`.
// Nothing is assumed about the indices themselves: out-of-range or repeated indices are the half-edge
// builder's job to report, with the face number.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace meshedit {

struct PolygonMesh {
  std::vector<glm::dvec3> positions;
  std::vector<uint32_t> indices;
  std::vector<uint32_t> face_offsets{0};

  size_t num_vertices() const { return positions.size(); }
  size_t num_faces() const { return face_offsets.size() - 1; }

  std::span<const uint32_t> face(size_t i) const {
    return {indices.data() + face_offsets[i], face_offsets[i + 1] - face_offsets[i]};
  }

  void add_face(std::span<const uint32_t> corners) {
    indices.insert(indices.end(), corners.begin(), corners.end());
    face_offsets.push_back(static_cast<uint32_t>(indices.size()));
  }
  void add_face(std::initializer_list<uint32_t> corners) {
    add_face(std::span<const uint32_t>(corners.begin(), corners.size()));
  }
  uint32_t add_vertex(const glm::dvec3& p) {
    positions.push_back(p);
    return static_cast<uint32_t>(positions.size() - 1);
  }

  // Appends `other`, shifting its indices past this mesh's vertices (used to merge glTF primitives).
  void append(const PolygonMesh& other);
};

inline void PolygonMesh::append(const PolygonMesh& other) {
  const auto base = static_cast<uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (size_t f = 0; f < other.num_faces(); ++f) {
    for (uint32_t i : other.face(f)) indices.push_back(i + base);
    face_offsets.push_back(static_cast<uint32_t>(indices.size()));
  }
}

}  // namespace meshedit
