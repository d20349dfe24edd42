// Reading a flip's, split's or collapse's geometry from the mesh's two states (see edit_motion.h). Each reader is a
// template over the two states' types: HalfedgeMesh, or StateBefore (the state before a patch).
#include "render/edit_motion.h"

#include <utility>
#include <vector>

#include "core/state_before.h"

namespace meshedit {
namespace {

struct EdgeEnds {
  HalfedgeId h0;
  VertexId a, b;  // a = h0.vertex, b = h0.twin.vertex
};

// The ends of h0's edge as h0 runs: a = h0.vertex, b = h0.twin.vertex.
template <class Mesh>
std::optional<EdgeEnds> ends_from(const Mesh& mesh, HalfedgeId h0) {
  if (!mesh.alive(h0)) return std::nullopt;
  const HalfedgeId h1 = mesh.twin(h0);
  if (!mesh.alive(h1)) return std::nullopt;
  const VertexId a = mesh.vertex(h0), b = mesh.vertex(h1);
  if (!mesh.alive(a) || !mesh.alive(b)) return std::nullopt;
  return EdgeEnds{h0, a, b};
}

// e's ends, from e.halfedge.
template <class Mesh>
std::optional<EdgeEnds> ends_of(const Mesh& mesh, EdgeId e) {
  if (!mesh.alive(e)) return std::nullopt;
  return ends_from(mesh, mesh.halfedge(e));
}

// The positions of the far ends of v's edges, except the ends `skip_1` and `skip_2`, walking h = h.twin.next from
// v.halfedge; false when the walk meets a dead element or does not close within kMaxWalk.
template <class Mesh>
bool far_ends(const Mesh& mesh, VertexId v, VertexId skip_1, VertexId skip_2, std::vector<glm::dvec3>& out) {
  const HalfedgeId start = mesh.halfedge(v);
  HalfedgeId h = start;
  for (size_t step = 0; step < kMaxWalk; ++step) {
    if (!mesh.alive(h) || mesh.vertex(h) != v) return false;
    const HalfedgeId twin = mesh.twin(h);
    if (!mesh.alive(twin)) return false;
    const VertexId far = mesh.vertex(twin);
    if (!mesh.alive(far)) return false;
    if (far != skip_1 && far != skip_2) out.push_back(mesh.position(far));
    h = mesh.next(twin);
    if (h == start) return true;
  }
  return false;
}

template <class Start, class Result>
std::optional<EditMotion> flip_motion(EdgeId e, const Start& start, const Result& result) {
  const auto before = ends_of(start, e);
  if (!before || !result.alive(e)) return std::nullopt;
  const auto after = ends_from(result, before->h0);
  if (!after) return std::nullopt;
  const VertexId d = after->a, c = after->b;  // h0 runs d->c after the flip
  if (before->a == d && before->b == c) return std::nullopt;
  return FlipMotion{start.position(before->a), start.position(before->b), result.position(c), result.position(d)};
}

template <class Start, class Result>
std::optional<EditMotion> split_motion(EdgeId e, const Start& start, const Result& result) {
  const auto before = ends_of(start, e);
  const auto after = ends_of(result, e);
  if (!before || !after) return std::nullopt;
  const bool first_new = !start.alive(after->a), second_new = !start.alive(after->b);
  if (first_new == second_new) return std::nullopt;  // no new end, or two
  const VertexId m = first_new ? after->a : after->b;
  SplitMotion split{start.position(before->a), start.position(before->b), result.position(m), {}};
  if (!far_ends(result, m, before->a, before->b, split.new_edge_ends)) return std::nullopt;
  return split;
}

template <class Start, class Result>
std::optional<EditMotion> collapse_motion(EdgeId e, const Start& start, const Result& result) {
  const auto before = ends_of(start, e);
  if (!before) return std::nullopt;
  const bool first_kept = result.alive(before->a), second_kept = result.alive(before->b);
  if (first_kept == second_kept) return std::nullopt;  // both ends kept, or neither
  const VertexId kept = first_kept ? before->a : before->b;
  const VertexId gone = first_kept ? before->b : before->a;
  CollapseMotion collapse{start.position(kept), start.position(gone), result.position(kept), {}, {}};
  if (!far_ends(start, kept, gone, gone, collapse.a_neighbours)) return std::nullopt;
  if (!far_ends(start, gone, kept, kept, collapse.b_neighbours)) return std::nullopt;
  return collapse;
}

template <class Start, class Result>
std::optional<EditMotion> motion_of(EdgeOperation operation, EdgeId e, const Start& start, const Result& result) {
  switch (operation) {
    case EdgeOperation::Flip: return flip_motion(e, start, result);
    case EdgeOperation::Split: return split_motion(e, start, result);
    case EdgeOperation::Collapse: return collapse_motion(e, start, result);
  }
  return std::nullopt;
}

}  // namespace

std::optional<EditMotion> edit_motion(EdgeOperation operation, EdgeId edge, const HalfedgeMesh& start,
                                      const HalfedgeMesh& result) {
  return motion_of(operation, edge, start, result);
}

std::optional<EditAnimation> edit_animation_of_change(EdgeOperation operation, EdgeId edge, bool undone,
                                                      const HalfedgeMesh& mesh, const MeshPatch& patch) {
  const StateBefore before(mesh, patch);
  std::optional<EditMotion> motion =
      undone ? motion_of(operation, edge, mesh, before) : motion_of(operation, edge, before, mesh);
  if (!motion) return std::nullopt;
  return EditAnimation{std::move(*motion), undone ? PlayDirection::Backward : PlayDirection::Forward};
}

}  // namespace meshedit
