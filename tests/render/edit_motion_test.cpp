// The geometry of a flip, split and collapse read from real edits (render/edit_motion.h): the patch an operation
// leaves and the mesh after it give the operation's corners, an undo (the reversed patch on the mesh put back) gives
// the same geometry played backward, and states that do not show the operation named give nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "render/edit_motion.h"
#include "support/journaled_edit.h"

namespace meshedit {
namespace {

// The flip lesson's diamond: v0 = a, v1 = b, v2 = c, v3 = d in mesh_ops.h's names for e0 (h0 runs v0->v1).
HalfedgeMesh diamond() {
  PolygonMesh p;
  p.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({1, 0, 3});
  return build_halfedge_mesh(p);
}

// An octahedron: v0 +x, v1 -x, v2 +y, v3 -y, v4 +z, v5 -z; e0 joins v0 and v2 (h0 runs v0->v2).
HalfedgeMesh octahedron() {
  PolygonMesh p;
  p.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& f : {std::array<uint32_t, 3>{0, 2, 4},
                        {2, 1, 4},
                        {1, 3, 4},
                        {3, 0, 4},
                        {2, 0, 5},
                        {1, 2, 5},
                        {3, 1, 5},
                        {0, 3, 5}}) {
    p.add_face({f[0], f[1], f[2]});
  }
  return build_halfedge_mesh(p);
}

std::vector<glm::dvec3> sorted(std::vector<glm::dvec3> points) {
  std::sort(points.begin(), points.end(),
            [](const glm::dvec3& p, const glm::dvec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); });
  return points;
}

// The animation of the edit on `mesh`, and of its undo (the reversed patch, on the mesh put back as it was).
template <class Op>
std::pair<std::optional<EditAnimation>, std::optional<EditAnimation>> edit_and_undo(HalfedgeMesh& mesh,
                                                                                    EdgeOperation operation, Op op) {
  const HalfedgeMesh start = mesh;
  const MeshPatch patch = testing::patch_of(mesh, op);
  auto edit = edit_animation_of_change(operation, EdgeId(0), false, mesh, patch);
  HalfedgeMesh undone = mesh;
  patch.apply(undone, false);
  EXPECT_TRUE(undone.same_as(start));
  auto undo = edit_animation_of_change(operation, EdgeId(0), true, undone, patch.reversed());
  return {std::move(edit), std::move(undo)};
}

TEST(EditMotion, AFlipsEndsGoFromAAndBToDAndC) {
  HalfedgeMesh mesh = diamond();
  const auto [edit, undo] =
      edit_and_undo(mesh, EdgeOperation::Flip, [](HalfedgeMesh& m) { ASSERT_TRUE(flip(m, EdgeId(0))); });
  ASSERT_TRUE(edit);
  EXPECT_EQ(edit->direction, PlayDirection::Forward);
  const FlipMotion& flip = std::get<FlipMotion>(edit->motion);
  EXPECT_EQ(flip.a, glm::dvec3(-1, 0, 0));
  EXPECT_EQ(flip.b, glm::dvec3(1, 0, 0));
  EXPECT_EQ(flip.c, glm::dvec3(0, 1, 0));
  EXPECT_EQ(flip.d, glm::dvec3(0, -1, 0));
  ASSERT_TRUE(undo);
  EXPECT_EQ(undo->direction, PlayDirection::Backward);
  const FlipMotion& back = std::get<FlipMotion>(undo->motion);
  EXPECT_EQ(back.a, flip.a);
  EXPECT_EQ(back.b, flip.b);
  EXPECT_EQ(back.c, flip.c);
  EXPECT_EQ(back.d, flip.d);
}

TEST(EditMotion, ASplitsNewVertexAndItsNewEdgesAreRead) {
  HalfedgeMesh mesh = diamond();
  const auto [edit, undo] =
      edit_and_undo(mesh, EdgeOperation::Split, [](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(0))); });
  ASSERT_TRUE(edit);
  EXPECT_EQ(edit->direction, PlayDirection::Forward);
  const SplitMotion& split = std::get<SplitMotion>(edit->motion);
  EXPECT_EQ(split.a, glm::dvec3(-1, 0, 0));
  EXPECT_EQ(split.b, glm::dvec3(1, 0, 0));
  EXPECT_EQ(split.m, glm::dvec3(0, 0, 0));
  EXPECT_EQ(sorted(split.new_edge_ends), (std::vector<glm::dvec3>{{0, -1, 0}, {0, 1, 0}}));
  ASSERT_TRUE(undo);
  EXPECT_EQ(undo->direction, PlayDirection::Backward);
  const SplitMotion& back = std::get<SplitMotion>(undo->motion);
  EXPECT_EQ(back.m, split.m);
  EXPECT_EQ(sorted(back.new_edge_ends), sorted(split.new_edge_ends));
}

TEST(EditMotion, ASplitBoundaryEdgeGrowsOneNewEdge) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  p.add_face({0, 1, 2});
  HalfedgeMesh mesh = build_halfedge_mesh(p);
  const auto [edit, undo] =
      edit_and_undo(mesh, EdgeOperation::Split, [](HalfedgeMesh& m) { ASSERT_TRUE(split(m, EdgeId(0))); });
  ASSERT_TRUE(edit);
  const SplitMotion& split = std::get<SplitMotion>(edit->motion);
  EXPECT_EQ(split.m, glm::dvec3(1, 0, 0));
  EXPECT_EQ(split.new_edge_ends, (std::vector<glm::dvec3>{{1, 1, 0}}));
}

TEST(EditMotion, ACollapsesEndsMeetAtTheMidpointAndTheirOtherEdgesAreRead) {
  HalfedgeMesh mesh = octahedron();
  const auto [edit, undo] =
      edit_and_undo(mesh, EdgeOperation::Collapse, [](HalfedgeMesh& m) { ASSERT_TRUE(collapse(m, EdgeId(0))); });
  ASSERT_TRUE(edit);
  EXPECT_EQ(edit->direction, PlayDirection::Forward);
  const CollapseMotion& collapse = std::get<CollapseMotion>(edit->motion);
  EXPECT_EQ(collapse.a, glm::dvec3(1, 0, 0));  // v0 survives (collapse keeps h0's vertex)
  EXPECT_EQ(collapse.b, glm::dvec3(0, 1, 0));
  EXPECT_EQ(collapse.meet, glm::dvec3(0.5, 0.5, 0));
  EXPECT_EQ(sorted(collapse.a_neighbours), (std::vector<glm::dvec3>{{0, -1, 0}, {0, 0, -1}, {0, 0, 1}}));
  EXPECT_EQ(sorted(collapse.b_neighbours), (std::vector<glm::dvec3>{{-1, 0, 0}, {0, 0, -1}, {0, 0, 1}}));
  ASSERT_TRUE(undo);
  EXPECT_EQ(undo->direction, PlayDirection::Backward);
  const CollapseMotion& back = std::get<CollapseMotion>(undo->motion);
  EXPECT_EQ(back.a, collapse.a);
  EXPECT_EQ(back.b, collapse.b);
  EXPECT_EQ(back.meet, collapse.meet);
  EXPECT_EQ(sorted(back.a_neighbours), sorted(collapse.a_neighbours));
  EXPECT_EQ(sorted(back.b_neighbours), sorted(collapse.b_neighbours));
}

TEST(EditMotion, StatesThatDoNotShowTheOperationGiveNothing) {
  const HalfedgeMesh mesh = diamond();
  for (const EdgeOperation operation : {EdgeOperation::Flip, EdgeOperation::Split, EdgeOperation::Collapse}) {
    EXPECT_FALSE(edit_motion(operation, EdgeId(0), mesh, mesh));  // nothing happened
    EXPECT_FALSE(edit_motion(operation, EdgeId(9), mesh, mesh));  // no such edge
  }
  HalfedgeMesh flipped = diamond();
  ASSERT_TRUE(flip(flipped, EdgeId(0)));
  EXPECT_TRUE(edit_motion(EdgeOperation::Flip, EdgeId(0), mesh, flipped));
  EXPECT_FALSE(edit_motion(EdgeOperation::Split, EdgeId(0), mesh, flipped));     // no new end
  EXPECT_FALSE(edit_motion(EdgeOperation::Collapse, EdgeId(0), mesh, flipped));  // both ends kept
  EXPECT_FALSE(edit_motion(EdgeOperation::Flip, EdgeId(1), mesh, flipped));      // e1 did not turn
}

TEST(EditMotion, ABrokenFanGivesNothingRatherThanAWalkWithoutEnd) {
  HalfedgeMesh before = octahedron();
  HalfedgeMesh after = before;
  ASSERT_TRUE(collapse(after, EdgeId(0)));
  // A script points a halfedge around v0 at a dead element: the walk around v0 in the state before stops there.
  HalfedgeMesh dead_end = before;
  const HalfedgeId h = before.halfedge(VertexId(0));
  dead_end.set_next(dead_end.twin(h), HalfedgeId(9999));
  EXPECT_FALSE(edit_motion(EdgeOperation::Collapse, EdgeId(0), dead_end, after));
  // Or at a halfedge of v0 whose own walk comes back to itself: the walk never meets v0's first halfedge again.
  HalfedgeMesh circling = before;
  const HalfedgeId second = circling.next(circling.twin(h));
  circling.set_next(circling.twin(second), second);
  EXPECT_FALSE(edit_motion(EdgeOperation::Collapse, EdgeId(0), circling, after));
  EXPECT_TRUE(edit_motion(EdgeOperation::Collapse, EdgeId(0), before, after));
}

}  // namespace
}  // namespace meshedit
