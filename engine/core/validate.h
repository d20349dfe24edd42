// validate(): every broken invariant of a half-edge mesh, as a structured report.
//
// Checked (each violation names the element, the invariant and a sentence with ids):
//   DeadReference      a live element points to a dead, invalid or out-of-range element
//   TwinOfTwin         twin(twin(h)) != h, or twin(h) == h
//   TwinEdge           h and twin(h) do not share their edge, e.halfedge does not lie on e, or more than two
//                      halfedges lie on e
//   FaceCycle          f's next-cycle does not close, has fewer than 3 halfedges, or holds a halfedge
//                      whose face is not f; or f.halfedge's face is not f; or a halfedge whose face is f
//                      is not in f's cycle. Boundary loops are checked like faces, also needing >= 3
//                      halfedges: a loop of 2 would be two edges joining the same two vertices, which no
//                      manifold built from faces of >= 3 corners has (the builder cannot make one).
//   NextNotPermutation a halfedge is the next of two halfedges, or of none
//   VertexHalfedge     v.halfedge does not leave v
//   VertexFan          the fan twin->next around v does not close, or misses some halfedge leaving v
//                      (an hourglass), or more than one boundary halfedge leaves v (v is on the boundary
//                      twice: two holes, or one hole pinched at v)
//   Orphan             a live element no live element refers to (an edge with no halfedges, a vertex
//                      no halfedge leaves, a face or boundary loop no halfedge lies in), or one with only
//                      boundary loops around it (a vertex whose fan holds no face, an edge with boundary
//                      loops on both sides)
//   NonFinitePosition  a coordinate is NaN or infinite
// Violations are reported on the element to fix where one is clear: FaceCycle membership problems on
// the halfedge, cycle shape problems on the face. A walk that meets a dead pointer stops without a report
// of its own (DeadReference names the pointer), so most breakages give one or two violations, not dozens.
// The checks use bounded walks only: validate() ends on any mesh, however broken, in O(H) time, and
// never reads an array through an id before checking that the id is live.
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
  ElementRef element;  // the element to select to see the problem
  Invariant invariant;
  std::string message;  // e.g. "h12.twin is h40, but h40.twin is h13 (should be h12)"
};

struct ValidationReport {
  // At most the cap passed to validate(): sorted by invariant (enum order), then element (kind, then id),
  // then the order found; the cap keeps the first ones in that order.
  std::vector<Violation> violations;
  size_t total = 0;  // every violation found, including those past the cap

  bool ok() const { return total == 0; }
  // "valid" or "3 problems; first: h12.twin is h40, but h40.twin is h13 (should be h12)"
  std::string summary() const;
};

// How many violations a report lists by default (it counts them all).
inline constexpr size_t kListedViolations = 100;

// Starts with quick_check.h's mesh_is_clean, so a valid mesh costs a few array passes (on up to `threads` threads;
// the report does not depend on the count).
ValidationReport validate(const HalfedgeMesh& mesh, size_t max_violations = kListedViolations, int threads = 1);
// Every check, always (for tests of the quick path).
ValidationReport validate_without_shortcut(const HalfedgeMesh& mesh, size_t max_violations = kListedViolations);

}  // namespace meshedit
