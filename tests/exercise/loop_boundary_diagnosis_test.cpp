// diagnose_loop_boundary on a subdivided 2x2 grid: the reference's own result has nothing to say; a boundary
// vertex moved by the interior rule, a boundary edge's new vertex at the interior rule with d read across the
// boundary loop, at 3/8 (a + b) + 1/8 c, or elsewhere, are each named with the vertex, the edge and the course's rule;
// interior mistakes are left to loop_position_diagnosis.h.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/loop_rules.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "exercise/internal/loop_boundary_diagnosis.h"

namespace meshedit {
namespace {

constexpr double kTolerance = 1e-9;

struct Subdivided {
  HalfedgeMesh before, after;
};

Subdivided grid_2x2() {
  Subdivided s{build_halfedge_mesh(make_grid(2, 2)), {}};
  s.after = s.before;
  EXPECT_TRUE(loop_subdivide(s.after).ok);
  return s;
}

// The new vertex of `after` between the original vertices a and b (its id is past `before`'s).
VertexId new_vertex_between(const Subdivided& s, VertexId a, VertexId b) {
  const glm::dvec3 mid = 0.5 * (s.before.position(a) + s.before.position(b));
  for (VertexId w : s.after.vertices()) {
    if (w.index >= s.before.vertex_capacity() && glm::distance(s.after.position(w), mid) < 1e-12) return w;
  }
  return {};
}

// The boundary halfedge of `before` (its face is the boundary loop) running from v0.
HalfedgeId boundary_halfedge_from(const HalfedgeMesh& mesh, VertexId v) {
  HalfedgeId found;
  mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    if (mesh.face(h).is_boundary()) found = h;
  });
  return found;
}

TEST(LoopBoundaryDiagnosis, TheReferencesOwnResultHasNothingToSay) {
  const Subdivided s = grid_2x2();
  EXPECT_TRUE(diagnose_loop_boundary(s.before, s.after, kTolerance).empty());
}

TEST(LoopBoundaryDiagnosis, ABoundaryVertexMovedByTheInteriorRuleIsNamed) {
  Subdivided s = grid_2x2();
  const VertexId v(0);  // the grid's corner (0, 0): 3 neighbours, 2 of them along the boundary
  glm::dvec3 sum(0.0);
  size_t n = 0;
  s.before.for_each_outgoing(v, [&](HalfedgeId h) {
    sum += s.before.position(s.before.vertex(s.before.twin(h)));
    ++n;
  });
  ASSERT_EQ(n, 3u);
  const glm::dvec3 interior = loop_rules::interior_vertex(s.before.position(v), sum, 3, 3.0 / 16.0);
  ASSERT_GT(glm::distance(interior, s.after.position(v)), 1e-3);
  s.after.set_position(v, interior);
  const std::vector<std::string> messages = diagnose_loop_boundary(s.before, s.after, kTolerance);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0],
            "1 of your boundary vertices, e.g. v0 (3 neighbours, 2 of them along the boundary), moved by the interior "
            "rule (1 - n u) p + u (sum of all the neighbours); a boundary vertex moves to 3/4 p + 1/8 (a + b), with a "
            "and b its two neighbours along the boundary (extra credit)");
}

TEST(LoopBoundaryDiagnosis, ABoundaryEdgePointByTheInteriorRuleIsNamedWithItsEdge) {
  Subdivided s = grid_2x2();
  const HalfedgeId outside = boundary_halfedge_from(s.before, VertexId(0));
  ASSERT_TRUE(outside.valid());
  const HalfedgeId inside = s.before.twin(outside);
  const VertexId a = s.before.vertex(inside), b = s.before.vertex(outside);
  const VertexId w = new_vertex_between(s, a, b);
  ASSERT_TRUE(w.valid());
  const glm::dvec3 pa = s.before.position(a), pb = s.before.position(b);
  const glm::dvec3 c = s.before.position(s.before.vertex(s.before.next(s.before.next(inside))));
  const glm::dvec3 d = s.before.position(s.before.vertex(s.before.next(s.before.next(outside))));
  const std::string edge = "v" + std::to_string(w.index) + " on the boundary edge v" + std::to_string(a.index) + "-v" +
                           std::to_string(b.index);

  s.after.set_position(w, loop_rules::interior_edge(pa, pb, c, d));
  std::vector<std::string> messages = diagnose_loop_boundary(s.before, s.after, kTolerance);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], "1 of your new vertices, e.g. " + edge +
                             ", are at the interior rule 3/8 (a + b) + 1/8 (c + d) with d read across the boundary "
                             "(h.twin.next.next walks the boundary loop, not a triangle); a boundary edge's new vertex "
                             "goes at its midpoint, (a + b) / 2 (extra credit)");

  s.after.set_position(w, 0.375 * (pa + pb) + 0.125 * c);
  messages = diagnose_loop_boundary(s.before, s.after, kTolerance);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], "1 of your new vertices, e.g. " + edge +
                             ", are at 3/8 (a + b) + 1/8 c, the interior rule with d left out; a boundary edge's new "
                             "vertex goes at its midpoint, (a + b) / 2 (extra credit)");

  s.after.set_position(w, glm::dvec3(0.25, -1.0, 0.0));
  messages = diagnose_loop_boundary(s.before, s.after, kTolerance);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], "1 of your new vertices on boundary edges are not at the midpoint, e.g. " + edge +
                             " at (0.25, -1, 0): a boundary edge's new vertex goes at its midpoint, (a + b) / 2 (extra "
                             "credit)");
}

TEST(LoopBoundaryDiagnosis, InteriorMistakesAndUnmovedVerticesAreLeftToTheOtherDiagnoses) {
  Subdivided s = grid_2x2();
  const VertexId centre(4);  // the grid's middle vertex (1, 1): interior
  ASSERT_EQ(s.before.position(centre), glm::dvec3(1, 1, 0));
  s.after.set_position(centre, glm::dvec3(5, 5, 5));
  s.after.set_position(VertexId(0), s.before.position(VertexId(0)));  // a boundary vertex left where it was
  EXPECT_TRUE(diagnose_loop_boundary(s.before, s.after, kTolerance).empty());
}

}  // namespace
}  // namespace meshedit
