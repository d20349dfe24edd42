// The Inspector panel: every stored field of the selected element as links, plus what can be derived by walking
// (degree, the face's halfedge cycle, the vertex's outgoing halfedges, prev, is-boundary, edge length).
//
// Invariants:
// - Derived facts come from bounded walks (at most halfedge_capacity() steps) and are computed once per
//   (document generation, mesh version, element), never every frame: a face with a million halfedges, or a
//   next-cycle a script bent into a rho, costs one walk, and the panel keeps drawing.
// - Stored fields of a dead element are shown (greyed) as their last values; nothing is walked from it.
// - Lists are cut at InspectorState::max_listed entries and say how many were left out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/halfedge_mesh.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "ui/element_link.h"

namespace meshedit {

// One step of a walk: the halfedge, and the vertex it names (a face cycle lists each halfedge's own vertex,
// the corner; a vertex fan lists each outgoing halfedge's far end, the neighbour: h.twin.vertex).
struct WalkEntry {
  HalfedgeId halfedge;
  VertexId vertex;  // invalid when it could not be read (a broken twin)
};

struct ElementFacts {
  ElementRef element;
  RefState state = RefState::Null;
  // Face / boundary loop: its next-cycle from f.halfedge. Vertex: its outgoing fan from v.halfedge (twin.next).
  std::vector<WalkEntry> walk;   // the first max_listed steps
  uint32_t walked = 0;           // steps taken before the walk closed or stopped
  bool closed = false;           // the walk came back to where it started
  bool is_boundary = false;      // vertex/edge on a boundary loop; halfedge inside one; element is a loop
  HalfedgeId prev;               // halfedge: the one whose next it is (invalid if its cycle is broken)
  VertexId head;                 // halfedge: next.vertex, where its arrow points
  HalfedgeId edge_twin;          // edge: e.halfedge.twin
  VertexId edge_ends[2];         // edge: e.halfedge.vertex, e.halfedge.twin.vertex
  FaceId edge_faces[2];          // edge: e.halfedge.face, e.halfedge.twin.face
  std::optional<double> length;  // edge: distance between its ends, when both are alive
  // Vertex and face degree as the course defines it: the number of steps of a closed walk, else absent.
  std::optional<uint32_t> degree() const { return closed ? std::optional<uint32_t>(walked) : std::nullopt; }
};

// The derived facts of one element. Safe on any mesh; O(length of the walk) <= O(halfedge_capacity()).
ElementFacts inspect_element(const HalfedgeMesh& mesh, ElementRef element, size_t max_listed);

struct InspectorState {
  bool open = true;
  size_t max_listed = 32;
  UiProbe* probe = nullptr;  // tests: where links were drawn
  // The facts of the element last shown, and the key they were computed for.
  ElementFacts facts;
  bool facts_filled = false;
  uint64_t facts_generation = 0, facts_version = 0;
  size_t facts_computations = 0;
};

// Draws the "Inspector" window (nothing when state.open is false). Clicking a link selects its element.
// Returns true when the selection changed.
bool draw_inspector(MeshDocument& doc, Selection& selection, InspectorState& state);
// The same contents, into the current window (for embedding in a window of the app's own).
bool draw_inspector_contents(MeshDocument& doc, Selection& selection, InspectorState& state);

}  // namespace meshedit
