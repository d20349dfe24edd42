// The student's mesh and the reference's at each of Loop subdivision's phase boundaries, side by side: what the
// Exercises tab shows beside the replay of a student's upsample (upsample_phases.h finds the boundaries).
//
//   const UpsamplePhases phases = find_upsample_phases(edits);
//   const UpsamplePhaseStates states = upsample_phase_states(before, edits, phases);
//   states.at[2].mine.vertices, states.at[2].reference.vertices, states.at[2].positions_differ, ...
//
// Yours at phase p is the replay up to phases.end_position(p) (the mesh when phase p is complete, or, for a phase
// that never started, what the phases below it left); the reference's is the core's phases (loop_subdivision.h) run
// on `before`: 1 nothing changed (the positions are computed aside), 2 after loop_split_edges, 3 after
// loop_flip_edges, 4 after loop_commit_positions.
//
// Invariants:
// - Differences are counted by id, as a student reads the tables: a vertex whose position differs (beyond
//   mesh_compare.h's mesh_tolerance(before), the finished upsample's tolerance) or that is alive in one mesh only,
//   and a halfedge whose next, twin, vertex, edge or face differs or that is alive in one only. `same_shape` is the
//   verdict up to renumbering (compare_meshes), so a student who splits in another order still sees where the shapes
//   agree.
// - When the core refuses to subdivide `before` (not triangles, ...), `refused` holds its reason and only yours are
//   filled.
// - Throws MeshError when the edits do not replay on `before` (see edit_log.h), std::bad_alloc when memory runs out;
//   nothing else.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"
#include "exercise/upsample_phases.h"

namespace meshedit {

struct MeshCounts {
  size_t vertices = 0, edges = 0, faces = 0;
  bool operator==(const MeshCounts&) const = default;
};
MeshCounts counts_of(const HalfedgeMesh& mesh);

struct UpsamplePhaseState {
  bool started = false;  // the phase wrote something (phase 1: always)
  size_t position = 0;   // the replay position of yours at this boundary
  MeshCounts mine, reference;
  size_t positions_differ = 0;  // vertices, by id
  size_t halfedges_differ = 0;  // halfedges, by id
  bool same_shape = false;      // equal to the reference's up to renumbering
  bool identical() const { return positions_differ == 0 && halfedges_differ == 0 && mine == reference; }
};

struct UpsamplePhaseStates {
  std::array<UpsamplePhaseState, 5> at{};  // [1] .. [4]
  std::string refused;                     // the core's reason when it does not subdivide `before`
};

// Vertices whose positions differ and halfedges whose pointers differ between two meshes, by id (see above).
struct IdDifferences {
  size_t positions = 0, halfedges = 0;
};
IdDifferences differences_by_id(const HalfedgeMesh& yours, const HalfedgeMesh& reference, double tolerance);

UpsamplePhaseStates upsample_phase_states(const HalfedgeMesh& before, std::span<const RecordedEdit> edits,
                                          const UpsamplePhases& phases);

}  // namespace meshedit
