// MeshReferences: how many live elements point at each vertex and halfedge slot through the pointers the renderer
// follows backwards (no GL). An incremental update uses the counts as certificates: having found some elements
// that point at a slot, it knows it found them all when their number equals the count, on any mesh, broken or not
// (incremental_update.h).
//
// Invariant: after count(mesh), or after apply(before, after, ...) given every halfedge and edge whose fields differ
// between the two states, the counts are exactly those of the current mesh. Pointers to dead or out-of-range
// slots are not counted (nothing reads through them).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/state_before.h"

namespace meshedit {

struct MeshReferences {
  std::vector<uint32_t> outgoing;   // per vertex slot: live halfedges h with h.vertex == v
  std::vector<uint32_t> twin_refs;  // per halfedge slot: live halfedges whose twin it is
  std::vector<uint32_t> edge_refs;  // per halfedge slot: live edges whose halfedge it is

  static MeshReferences count(const HalfedgeMesh& mesh);
  // From the counts of `before` to those of `after`: `halfedges` and `edges` list every slot (of either state) whose
  // fields differ, each once. O(listed slots), plus a resize when the capacities change.
  void apply(const HalfedgeMesh& before, const HalfedgeMesh& after, std::span<const uint32_t> halfedges,
             std::span<const uint32_t> edges);
  // The same with the state before read through the edit's patch.
  void apply(const StateBefore& before, const HalfedgeMesh& after, std::span<const uint32_t> halfedges,
             std::span<const uint32_t> edges);
  bool operator==(const MeshReferences&) const = default;
};

}  // namespace meshedit
