// Helpers for the flip, split, collapse and stress tests: short id names, expectations that print ids the
// way the app does (h12, not raw bytes), and the checks every operation's result must pass.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/halfedge_mesh.h"
#include "core/validate.h"

namespace meshedit::ops_testing {

inline VertexId V(uint32_t i) { return VertexId(i); }
inline HalfedgeId H(uint32_t i) { return HalfedgeId(i); }
inline EdgeId E(uint32_t i) { return EdgeId(i); }
inline FaceId F(uint32_t i) { return FaceId::face(i); }
inline FaceId B(uint32_t i) { return FaceId::boundary(i); }

// Compares two ids (of any kind, including FaceId) by their printed form, so failures read "h13 vs h14".
#define EXPECT_ID(actual, expected) EXPECT_EQ(::meshedit::format_id(actual), ::meshedit::format_id(expected))

// Every field of halfedge h, and that it is alive.
inline void expect_halfedge(const HalfedgeMesh& m, HalfedgeId h, HalfedgeId next, HalfedgeId twin, VertexId vertex,
                            EdgeId edge, FaceId face) {
  SCOPED_TRACE(format_id(h));
  EXPECT_TRUE(m.alive(h));
  EXPECT_ID(m.next(h), next);
  EXPECT_ID(m.twin(h), twin);
  EXPECT_ID(m.vertex(h), vertex);
  EXPECT_ID(m.edge(h), edge);
  EXPECT_ID(m.face(h), face);
}

// validate() accepts the mesh, and every boundary vertex's halfedge is its outgoing boundary halfedge.
inline ::testing::AssertionResult valid_mesh(const HalfedgeMesh& m) {
  const ValidationReport report = validate(m);
  if (!report.ok()) return ::testing::AssertionFailure() << report.summary();
  for (VertexId v : m.vertices()) {
    if (m.is_boundary(v) && !m.face(m.halfedge(v)).is_boundary()) {
      const HalfedgeId h = m.halfedge(v);
      return ::testing::AssertionFailure() << format_id(v) << " is on a boundary but its halfedge " << format_id(h)
                                           << " lies in " << format_id(m.face(h));
    }
  }
  return ::testing::AssertionSuccess();
}

// What the link condition protects beyond validate(): no two edges join the same two vertices, no face uses a
// vertex twice, and no two faces have the same corners (a flattened tetrahedron).
inline ::testing::AssertionResult simplicial_mesh(const HalfedgeMesh& m) {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (EdgeId e : m.edges()) {
    const HalfedgeId h = m.halfedge(e);
    const uint32_t a = m.vertex(h).index, b = m.vertex(m.twin(h)).index;
    edges.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(edges.begin(), edges.end());
  if (auto it = std::adjacent_find(edges.begin(), edges.end()); it != edges.end()) {
    return ::testing::AssertionFailure() << "two edges join v" << it->first << " and v" << it->second;
  }
  std::vector<std::vector<uint32_t>> faces;
  for (FaceId f : m.faces()) {
    std::vector<uint32_t> c;
    m.for_each_face_halfedge(f, [&](HalfedgeId h) { c.push_back(m.vertex(h).index); });
    std::sort(c.begin(), c.end());
    if (std::adjacent_find(c.begin(), c.end()) != c.end()) {
      return ::testing::AssertionFailure() << format_id(f) << " uses a vertex twice";
    }
    faces.push_back(std::move(c));
  }
  std::sort(faces.begin(), faces.end());
  if (std::adjacent_find(faces.begin(), faces.end()) != faces.end()) {
    return ::testing::AssertionFailure() << "two faces have the same corners";
  }
  return ::testing::AssertionSuccess();
}

// The corners of f as vertex indices, starting at f.halfedge (empty if the cycle does not close).
inline std::vector<uint32_t> corners(const HalfedgeMesh& m, FaceId f) {
  std::vector<uint32_t> out;
  if (!m.for_each_face_halfedge(f, [&](HalfedgeId h) { out.push_back(m.vertex(h).index); })) out.clear();
  return out;
}

// V - E + F with F counting real faces only.
inline long euler_characteristic(const HalfedgeMesh& m) {
  return static_cast<long>(m.num_vertices()) - static_cast<long>(m.num_edges()) + static_cast<long>(m.num_faces());
}

// True if `reason` names at least one element the way format_id prints it (a letter, then digits).
inline bool names_an_element(const std::string& reason) {
  for (size_t i = 0; i + 1 < reason.size(); ++i) {
    const char c = reason[i];
    const bool boundary_of_word = i == 0 || !std::isalnum(static_cast<unsigned char>(reason[i - 1]));
    if (boundary_of_word && (c == 'v' || c == 'h' || c == 'e' || c == 'f' || c == 'b') &&
        std::isdigit(static_cast<unsigned char>(reason[i + 1]))) {
      return true;
    }
  }
  return false;
}

}  // namespace meshedit::ops_testing
