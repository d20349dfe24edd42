// diff() lists exactly the changed fields, in order; History restores exact meshes and ids, keeps its
// depth and labels, clears redo on record, and moves the version forward on undo and redo.
// Tetrahedron ids as in mesh_build.h: v1 = (1, -1, -1); h0 0->1 with next h1.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "core/history.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

HalfedgeMesh tetrahedron() { return build_halfedge_mesh(make_tetrahedron()); }

// "v1.position: (1, -1, -1) -> (0.5, 0, 1)", one per line.
std::string listing(const std::vector<FieldChange>& changes) {
  std::string s;
  for (const FieldChange& c : changes) {
    s += format_id(c.element) + "." + c.field + ": " + c.before + " -> " + c.after + "\n";
  }
  return s;
}

TEST(ValueFormat, ShortestExactText) {
  EXPECT_EQ(format_number(0.5), "0.5");
  EXPECT_EQ(format_number(1.0), "1");
  EXPECT_EQ(format_number(-0.0), "-0");
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_number(1e100), "1e+100");
  EXPECT_EQ(format_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_position({0.5, 0, 1}), "(0.5, 0, 1)");
}

TEST(Diff, IdenticalMeshesHaveNoChanges) {
  const HalfedgeMesh m = tetrahedron();
  EXPECT_TRUE(diff(m, m).empty());
  HalfedgeMesh same_values = m;
  same_values.set_next(HalfedgeId(0), HalfedgeId(1));  // rewrites the same value
  EXPECT_TRUE(diff(m, same_values).empty());
}

TEST(Diff, HandMadeChange) {
  const HalfedgeMesh before = tetrahedron();
  HalfedgeMesh after = before;
  after.set_next(HalfedgeId(0), HalfedgeId(2));
  after.set_position(VertexId(1), {0.5, 0, 1});
  after.new_vertex({1, 2, 3});
  const std::vector<FieldChange> changes = diff(before, after);
  ASSERT_EQ(changes.size(), 5u);
  EXPECT_EQ(changes[0].element, ElementRef(VertexId(1)));
  EXPECT_EQ(changes[0].field, "position");
  EXPECT_EQ(changes[0].before, "(1, -1, -1)");
  EXPECT_EQ(changes[0].after, "(0.5, 0, 1)");
  EXPECT_EQ(listing(changes),
            "v1.position: (1, -1, -1) -> (0.5, 0, 1)\n"
            "v4.halfedge: - -> -\n"
            "v4.position: - -> (1, 2, 3)\n"
            "v4.alive: - -> alive\n"
            "h0.next: h1 -> h2\n");
}

TEST(Diff, EveryFieldOfEveryKindInOrder) {
  const HalfedgeMesh before = build_halfedge_mesh(make_grid(1, 1));  // one boundary loop b0 = h6..h9
  HalfedgeMesh after = before;
  after.set_face(HalfedgeId(1), FaceId::boundary(0));
  after.set_edge(HalfedgeId(1), EdgeId(3));
  after.set_vertex(HalfedgeId(1), VertexId(2));
  after.set_twin(HalfedgeId(1), HalfedgeId(4));
  after.set_next(HalfedgeId(1), HalfedgeId(3));
  after.delete_element(FaceId::boundary(0));
  after.set_halfedge(FaceId::boundary(0), HalfedgeId(7));
  after.set_halfedge(FaceId::face(1), HalfedgeId(4));
  after.set_halfedge(EdgeId(2), HalfedgeId(3));
  after.delete_element(EdgeId(4));
  after.set_halfedge(VertexId(3), HalfedgeId());
  after.delete_element(VertexId(0));
  after.new_halfedge();
  after.new_boundary();
  EXPECT_EQ(listing(diff(before, after)),
            "v0.alive: alive -> dead\n"
            "v3.halfedge: h" +
                std::to_string(before.halfedge(VertexId(3)).index) +
                " -> -\n"
                "h1.next: h2 -> h3\n"
                "h1.twin: h" +
                std::to_string(before.twin(HalfedgeId(1)).index) +
                " -> h4\n"
                "h1.vertex: v1 -> v2\n"
                "h1.edge: e1 -> e3\n"
                "h1.face: f0 -> b0\n"
                "h10.next: - -> -\n"
                "h10.twin: - -> -\n"
                "h10.vertex: - -> -\n"
                "h10.edge: - -> -\n"
                "h10.face: - -> -\n"
                "h10.alive: - -> alive\n"
                "e2.halfedge: h2 -> h3\n"
                "e4.alive: alive -> dead\n"
                "f1.halfedge: h3 -> h4\n"
                "b0.halfedge: h6 -> h7\n"
                "b0.alive: alive -> dead\n"
                "b1.halfedge: - -> -\n"
                "b1.alive: - -> alive\n");
}

TEST(Diff, PositionsCompareBitForBit) {
  const HalfedgeMesh before = tetrahedron();
  HalfedgeMesh after = before;
  after.set_position(VertexId(0), {-0.0, 1, 1});         // was (1, 1, 1)
  after.set_position(VertexId(2), {-1, 1, -1 + 1e-16});  // tiny change must still show
  EXPECT_EQ(listing(diff(before, after)),
            "v0.position: (1, 1, 1) -> (-0, 1, 1)\n"
            "v2.position: (-1, 1, -1) -> (-1, 1, -0.9999999999999999)\n");
  HalfedgeMesh nan = before;
  nan.set_position(VertexId(3), {std::numeric_limits<double>::quiet_NaN(), 0, 0});
  EXPECT_TRUE(diff(nan, nan).empty());  // NaN equals itself bit for bit
}

TEST(Diff, SwappedArgumentsListTheExtraSlotsWithoutCrashing) {
  const HalfedgeMesh small = tetrahedron();
  HalfedgeMesh big = small;
  big.new_edge();
  EXPECT_EQ(listing(diff(big, small)),
            "e6.halfedge: - -> -\n"
            "e6.alive: alive -> -\n");
  EXPECT_EQ(diff(HalfedgeMesh(), small).size(), 4u * 3 + 12u * 6 + 6u * 2 + 4u * 2);
}

TEST(History, UndoRedoRestoreExactMeshes) {
  HalfedgeMesh m = tetrahedron();
  const HalfedgeMesh s0 = m;
  History history;
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.undo(m));
  EXPECT_FALSE(history.redo(m));
  EXPECT_TRUE(m.same_as(s0));

  history.record("move v1", m);
  m.set_position(VertexId(1), {0, 0, 0});
  const HalfedgeMesh s1 = m;
  history.record("add vertex", m);
  const VertexId added = m.new_vertex({5, 5, 5});
  const HalfedgeMesh s2 = m;
  EXPECT_EQ(added, VertexId(4));
  EXPECT_EQ(history.undo_depth(), 2u);
  EXPECT_EQ(history.undo_label(), "add vertex");
  EXPECT_EQ(history.redo_label(), "");

  ASSERT_TRUE(history.undo(m));
  EXPECT_TRUE(m.same_as(s1));
  EXPECT_FALSE(m.alive(added));  // an id from the future reads dead
  EXPECT_EQ(m.vertex_capacity(), 4u);
  EXPECT_EQ(history.undo_label(), "move v1");
  EXPECT_EQ(history.redo_label(), "add vertex");
  EXPECT_TRUE(history.can_redo());

  ASSERT_TRUE(history.undo(m));
  EXPECT_TRUE(m.same_as(s0));
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.undo(m));
  EXPECT_TRUE(m.same_as(s0));

  ASSERT_TRUE(history.redo(m));
  EXPECT_TRUE(m.same_as(s1));
  ASSERT_TRUE(history.redo(m));
  EXPECT_TRUE(m.same_as(s2));
  EXPECT_TRUE(m.alive(added));
  EXPECT_EQ(m.position(added), glm::dvec3(5, 5, 5));
  EXPECT_FALSE(history.redo(m));
  EXPECT_EQ(history.undo_label(), "add vertex");
}

TEST(History, RecordClearsRedo) {
  HalfedgeMesh m = tetrahedron();
  History history;
  history.record("a", m);
  m.set_next(HalfedgeId(0), HalfedgeId(2));
  ASSERT_TRUE(history.undo(m));
  ASSERT_TRUE(history.can_redo());
  history.record("b", m);
  m.delete_element(EdgeId(0));
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.redo_label(), "");
  EXPECT_FALSE(history.redo(m));
  EXPECT_EQ(history.undo_label(), "b");
  ASSERT_TRUE(history.undo(m));
  EXPECT_TRUE(m.same_as(tetrahedron()));
}

TEST(History, MaxDepthDropsTheOldest) {
  HalfedgeMesh m = tetrahedron();
  History history(2);
  std::vector<HalfedgeMesh> states{m};
  for (int i = 0; i < 3; ++i) {
    history.record("step " + std::to_string(i), m);
    m.set_position(VertexId(0), {double(i), 0, 0});
    states.push_back(m);
  }
  EXPECT_EQ(history.undo_depth(), 2u);
  ASSERT_TRUE(history.undo(m));
  EXPECT_TRUE(m.same_as(states[2]));
  EXPECT_EQ(history.undo_label(), "step 1");
  ASSERT_TRUE(history.undo(m));
  EXPECT_TRUE(m.same_as(states[1]));
  EXPECT_FALSE(history.undo(m));  // "step 0" was dropped
  EXPECT_TRUE(m.same_as(states[1]));
  // Redo brings both back; the depth still holds.
  ASSERT_TRUE(history.redo(m));
  ASSERT_TRUE(history.redo(m));
  EXPECT_TRUE(m.same_as(states[3]));
  EXPECT_EQ(history.undo_depth(), 2u);
}

TEST(History, ClearForgetsEverything) {
  HalfedgeMesh m = tetrahedron();
  History history;
  history.record("a", m);
  m.new_edge();
  ASSERT_TRUE(history.undo(m));
  history.record("b", m);
  history.clear();
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.undo_depth(), 0u);
  EXPECT_EQ(history.undo_label(), "");
}

TEST(History, VersionMovesForwardOnUndoAndRedo) {
  HalfedgeMesh m = tetrahedron();
  History history;
  const uint64_t v0 = m.version();
  history.record("edit", m);
  for (int i = 0; i < 5; ++i) m.set_position(VertexId(0), {double(i), 0, 0});
  const uint64_t v_edit = m.version();
  ASSERT_GT(v_edit, v0);
  ASSERT_TRUE(history.undo(m));
  EXPECT_GT(m.version(), v_edit);  // not v0: a cache that saw v0 must not think nothing changed since
  const uint64_t v_undo = m.version();
  ASSERT_TRUE(history.redo(m));
  EXPECT_GT(m.version(), v_undo);
}

}  // namespace
}  // namespace meshedit
