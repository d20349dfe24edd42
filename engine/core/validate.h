// validate(): every broken invariant of a half-edge mesh, as a structured report.
//
// Checked (each violation names the element, the invariant and a sentence with ids):
//   DeadReference      a live element points to a dead, invalid or out-of-range element
//   TwinOfTwin         twin(twin(h)) != h, or twin(h) == h
//   TwinEdge           h and twin(h) do not share their edge, or e.halfedge does not belong to e
//   FaceCycle          f's next-cycle does not close, has fewer than 3 halfedges, or holds a halfedge
//                      whose face is not f; or f.halfedge's face is not f
//   NextNotPermutation a halfedge is the next of two halfedges, or of none
//   VertexHalfedge     v.halfedge does not leave v
//   VertexFan          the fan twin->next around v does not close, or misses some halfedge leaving v
//                      (an hourglass), or v lies on more than one boundary loop
//   Orphan             a live element no live element refers to (an edge with no halfedges, a vertex
//                      no halfedge leaves, a face no halfedge lies in, a face that is only boundary)
//   NonFinitePosition  a coordinate is NaN or infinite
// The checks use bounded walks only: validate() ends on any mesh, however broken, in O(H) time.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/halfedge_mesh.h"

namespace meshedit {

enum class Invariant {
  DeadReference,
  TwinOfTwin,
  TwinEdge,
  FaceCycle,
  NextNotPermutation,
  VertexHalfedge,
  VertexFan,
  Orphan,
  NonFinitePosition,
};

// "twin of twin", "face cycle", ... (stable names for tests, Lua and JSON output).
const char* invariant_name(Invariant invariant);

struct Violation {
  ElementRef element;       // the element to select to see the problem
  Invariant invariant;
  std::string message;      // e.g. "h12.twin is h40, but h40.twin is h13 (should be h12)"
};

struct ValidationReport {
  std::vector<Violation> violations;  // at most the cap passed to validate(), in a stable order
  size_t total = 0;                   // every violation found, including those past the cap

  bool ok() const { return total == 0; }
  // "valid" or "3 problems; first: h12.twin is h40, but h40.twin is h13 (should be h12)"
  std::string summary() const;
};

ValidationReport validate(const HalfedgeMesh& mesh, size_t max_violations = 100);

}  // namespace meshedit
