// plan_update: the slots of the renderer's buffers (slot_geometry.h) that a change of the mesh rewrites, with their
// new values, found from the elements the change touched, in time proportional to them, not to the mesh. No GL.
//
// Given the state the buffers show (`before`), the new state (`after`) and every element whose fields differ
// between them (the document's diff), the patch rewrites every slot whose value differs (and a few around them that
// come out the same), so applying it to build_slot_geometry(before) gives build_slot_geometry(after), byte for byte
// (tests check it on long random runs of flips, splits, collapses, undos, redos and raw pointer writes). `before` may
// be a copy of the mesh or the state read through the edit's patch (StateBefore), with the same result. The dirty
// slots follow from what each value reads:
// - a face slot reads the face's walk (its halfedges' alive, face, next, vertex; its corners' alive and position):
//   it is dirty when the face changed, when a changed halfedge lies in it in either state, or when it has a
//   changed vertex as a corner in either state;
// - an edge slot reads its halfedge h, twin(h) and their vertices: dirty when the edge, h or twin(h) changed, or
//   when an end is a changed vertex;
// - a vertex's smooth normal reads only the drawn faces it is a corner of: dirty when it is a corner of a dirty face
//   in either state (or changed itself); a point reads only its vertex;
// - an arrow reads its face's drawn cycle: dirty when its halfedge changed or lies on a dirty face's cycle.
// Following those reads backwards needs "who points at this": the halfedges leaving a vertex (found by walking its
// fan), the halfedges whose twin is h, the edges whose halfedge is h. Each search is certified complete by the
// counts in MeshReferences (walked fan size == halfedges leaving the vertex, and so on), so a broken mesh cannot
// hide a dependency: when a certificate fails, or a polygon's number of fan triangles changes (its packed later
// triangles would move; the same number is rewritten in place), or a walk is longer than kMaxWalk, there is no patch
// and the caller rebuilds everything.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/state_before.h"
#include "render/mesh_references.h"
#include "render/slot_geometry.h"

namespace meshedit {

struct FacePatch {
  uint32_t face;
  std::array<uint32_t, 3> triangle;
  glm::vec4 normal;
};

struct SlotPatch {
  uint32_t vertex_capacity = 0, halfedge_capacity = 0, edge_capacity = 0, face_capacity = 0;  // of `after`
  std::vector<std::pair<uint32_t, VertexPoint>> points;  // also the positions: a point's position, 0 when hidden
  std::vector<std::pair<uint32_t, glm::vec3>> normals;
  std::vector<FacePatch> faces;
  std::vector<std::pair<uint32_t, std::array<uint32_t, 3>>> extra_triangles;  // packed index -> triangle
  std::vector<std::pair<uint32_t, EdgeSegment>> edges;
  std::vector<std::pair<uint32_t, std::array<EdgeSegment, 3>>> arrows;  // only when asked for
  bool boundary_changed = false;               // a boundary edge (before or after) is among the edges
  std::vector<uint32_t> boundary_edges;        // then: the whole new list of drawn boundary edges,
  std::vector<EdgeSegment> boundary_segments;  // and their segments (O(boundary edges), only then)
  SlotCounts counts;                           // of `after`
  BoundingBox bounds;                          // the old box grown by the moved points (it never shrinks)

  size_t slots() const {
    return points.size() + normals.size() + faces.size() + extra_triangles.size() + edges.size() + arrows.size();
  }
};

// What the renderer keeps between updates besides the GPU buffers.
struct SlotState {
  MeshReferences references;
  SlotCounts counts;
  std::vector<uint32_t> boundary_edges;
  BoundingBox bounds;
  std::vector<uint32_t> extra_first;  // per face slot: its first packed triangle (kInvalidIndex: none); empty when
                                      // no face has any
};

inline constexpr uint32_t kMaxWalk = 1024;  // longest face cycle or vertex fan an update walks

// The patch from `before` to `after`, or nullopt (with the reason in `why`) when the update must be a full
// rebuild. `changed`: every element with a field that differs, each once (boundary loops are ignored: nothing
// drawn reads them). `state` describes `before` and is advanced to `after` when a patch is returned; when not,
// it is left in no particular state (the caller rebuilds it). With `arrows`, the patch also rewrites the arrows.
std::optional<SlotPatch> plan_update(const HalfedgeMesh& before, const HalfedgeMesh& after,
                                     std::span<const ElementRef> changed, SlotState& state, bool arrows,
                                     std::string& why);
// The same with the state before read through the edit's patch (core/state_before.h): no copy of the mesh is needed,
// and the result is the same.
std::optional<SlotPatch> plan_update(const StateBefore& before, const HalfedgeMesh& after,
                                     std::span<const ElementRef> changed, SlotState& state, bool arrows,
                                     std::string& why);

// The state a full build leaves (for the renderer and the tests).
SlotState slot_state(const HalfedgeMesh& mesh, const SlotGeometry& g);

// Applies a patch to CPU-side slot arrays (the tests' mirror of what the renderer uploads).
void apply_patch(SlotGeometry& g, std::vector<EdgeSegment>* arrows, const SlotPatch& patch);

}  // namespace meshedit
