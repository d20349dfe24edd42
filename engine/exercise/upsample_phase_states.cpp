// Yours and the reference's at each phase boundary (see upsample_phase_states.h for the contract).
//
// Yours are made by one pass over the edits in the order of the boundaries' positions, so the whole costs one
// replay, not one per phase.
#include "exercise/upsample_phase_states.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "core/loop_subdivision.h"
#include "core/mesh_compare.h"

namespace meshedit {

MeshCounts counts_of(const HalfedgeMesh& mesh) { return {mesh.num_vertices(), mesh.num_edges(), mesh.num_faces()}; }

IdDifferences differences_by_id(const HalfedgeMesh& yours, const HalfedgeMesh& reference, double tolerance) {
  IdDifferences out;
  const uint32_t vertices = std::max(yours.vertex_capacity(), reference.vertex_capacity());
  for (uint32_t i = 0; i < vertices; ++i) {
    const VertexId v(i);
    const bool a = yours.alive(v), b = reference.alive(v);
    if (!a && !b) continue;
    if (a != b) {
      ++out.positions;
      continue;
    }
    const glm::dvec3 d = yours.position(v) - reference.position(v);
    // Written so that a NaN counts as a difference.
    if (!(std::abs(d.x) <= tolerance && std::abs(d.y) <= tolerance && std::abs(d.z) <= tolerance)) ++out.positions;
  }
  const uint32_t halfedges = std::max(yours.halfedge_capacity(), reference.halfedge_capacity());
  for (uint32_t i = 0; i < halfedges; ++i) {
    const HalfedgeId h(i);
    const bool a = yours.alive(h), b = reference.alive(h);
    if (!a && !b) continue;
    if (a != b || !(yours.record(h) == reference.record(h))) ++out.halfedges;
  }
  return out;
}

UpsamplePhaseStates upsample_phase_states(const HalfedgeMesh& before, std::span<const RecordedEdit> edits,
                                          const UpsamplePhases& phases) {
  UpsamplePhaseStates out;
  const double tolerance = mesh_tolerance(before);  // as the verdict on the finished upsample

  // The reference's four states.
  std::array<std::optional<HalfedgeMesh>, 5> reference;
  OpResult<LoopState> loop = loop_compute_positions(before, LoopWeights::Course);
  if (loop.ok()) {
    reference[1] = before;
    reference[2] = before;
    loop_split_edges(*reference[2], loop.value);
    reference[3] = *reference[2];
    loop_flip_edges(*reference[3], loop.value);
    reference[4] = *reference[3];
    loop_commit_positions(*reference[4], loop.value);
  } else {
    out.refused = loop.check.reason;
  }

  // Yours, in the order of the boundaries.
  std::array<int, 4> order = {1, 2, 3, 4};
  for (int p = 1; p <= kUpsamplePhaseCount; ++p) {
    out.at[size_t(p)].position = std::min(phases.end_position(UpsamplePhase(p)), edits.size());
    out.at[size_t(p)].started = phases.span[size_t(p)].started;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return out.at[size_t(a)].position < out.at[size_t(b)].position; });
  HalfedgeMesh mine = before;
  size_t applied = 0;
  for (const int p : order) {
    UpsamplePhaseState& state = out.at[size_t(p)];
    for (; applied < state.position; ++applied) apply_edit(mine, edits[applied]);
    state.mine = counts_of(mine);
    if (!reference[size_t(p)]) continue;
    const HalfedgeMesh& theirs = *reference[size_t(p)];
    state.reference = counts_of(theirs);
    const IdDifferences d = differences_by_id(mine, theirs, tolerance);
    state.positions_differ = d.positions;
    state.halfedges_differ = d.halfedges;
    CompareOptions options;
    options.position_tolerance = tolerance;
    options.max_differences = 1;
    state.same_shape = compare_meshes(mine, theirs, options).equal;
  }
  return out;
}

}  // namespace meshedit
